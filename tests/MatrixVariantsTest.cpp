// The matrix's variants (bench/golden/MatrixVariants.h, techniques/MatrixVariant.h): a technique's forms
// at other properties that have cells, goldens, bounds and rows of their own, keyed by their spec. The
// answers are the registry's declarations and cells made by hand (no renderer): every declared variant is
// a spec the technique takes, back as written, under a key that is a file name and no other form's;
// `--technique` selects a technique with its variants or one variant; a variant's cells are held to its
// own golden file and to the rule it declares, under its own key. The rendered cells are checked by
// `bench golden` on the driver that runs them (tests/CMakeLists.txt, MatrixOfSecondDriverTechniques).
#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "PaintedCell.h"
#include "TestSupport.h"
#include "bench/golden/AccuracyBounds.h"
#include "bench/golden/GoldenImage.h"
#include "bench/golden/GoldenMatrix.h"
#include "bench/golden/MatrixCheck.h"
#include "bench/golden/MatrixVariants.h"
#include "core/Error.h"
#include "registry/TechniqueRegistry.h"

using namespace sb;

namespace {

constexpr const char* kScene = "handmade";
constexpr int kSize = 16;

std::string joined(const std::vector<std::string>& lines) {
    std::string out;
    for (const std::string& l : lines) out += l + "\n";
    return out;
}

TEST(MatrixVariants, EveryDeclaredVariantIsASpecOfItsTechniqueWithAKeyOfItsOwn) {
    std::set<std::string> keys;
    size_t variants = 0;
    for (const std::string& form : MatrixVariants::all()) {
        const TechniqueSpec spec = TechniqueSpec::parse(form);
        EXPECT_EQ(spec.toString(), form) << "a variant is written as -t writes it back";
        EXPECT_NO_THROW(TechniqueRegistry::describe(spec)) << form << ": its properties apply";
        const std::string key = MatrixVariants::key(form);
        EXPECT_TRUE(keys.insert(key).second) << form << ": key " << key << " is another form's";
        EXPECT_EQ(
            key.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789.=-_,"),
            std::string::npos)
            << key;
        EXPECT_EQ(MatrixVariants::nameOf(form), spec.name);
        if (spec.properties.empty()) {
            EXPECT_EQ(key, form) << "a default form keeps the files it had";
            EXPECT_FALSE(MatrixVariants::variantOf(form).has_value()) << form;
        } else {
            ++variants;
            ASSERT_TRUE(MatrixVariants::variantOf(form).has_value()) << form;
            EXPECT_FALSE(MatrixVariants::variantOf(form)->why.empty()) << form << ": its rule needs a reason";
        }
    }
    EXPECT_EQ(MatrixVariants::all().size(), TechniqueRegistry::names().size() + variants);
}

// The variants raytraced declares, what they are keyed by and the rule each is held to.
TEST(MatrixVariants, RaytracedHasSoftAndGuidedCellsAtTheExactRule) {
    EXPECT_EQ(MatrixVariants::of("raytraced"),
              (std::vector<std::string>{"raytraced", "raytraced:mode=soft", "raytraced:mode=guided"}));
    EXPECT_EQ(MatrixVariants::key("raytraced:mode=soft"), "raytraced.mode=soft");
    EXPECT_EQ(MatrixVariants::key("raytraced:mode=guided"), "raytraced.mode=guided");
    // soft: the built-in scenes' lights have no extent, where soft traces hard's one ray; guided: its
    // maps' decisions measured equal to hard's rays off the edge band (techniques/raytraced/RayTraced.cpp).
    EXPECT_EQ(MatrixVariants::variantOf("raytraced:mode=soft")->rule, AccuracyRule::Exact);
    EXPECT_EQ(MatrixVariants::variantOf("raytraced:mode=guided")->rule, AccuracyRule::Exact);
    // Most techniques have none.
    EXPECT_EQ(MatrixVariants::of("pcss"), std::vector<std::string>{"pcss"});
}

// The variants only Vulkan has (MatrixVariant::glRefusal): their GL cells are cells of no form, with the
// reason; every other variant has a GL form where its technique has one.
TEST(MatrixVariants, SparsePagesAndMeshShadersAreVulkanOnlyVariants) {
    EXPECT_EQ(MatrixVariants::of("shadowmap"),
              (std::vector<std::string>{"shadowmap", "shadowmap:contact=true"}));
    EXPECT_TRUE(MatrixVariants::variantOf("shadowmap:contact=true")->glRefusal.empty());
    EXPECT_NE(MatrixVariants::variantOf("virtual:path=sparse")->glRefusal.find("sparse residency"),
              std::string::npos);
    EXPECT_EQ(MatrixVariants::variantOf("virtual:path=sparse")->rule, AccuracyRule::Map);
    EXPECT_NE(MatrixVariants::variantOf("volume:extrusion=mesh")->glRefusal.find("mesh shaders"),
              std::string::npos);
    EXPECT_EQ(MatrixVariants::variantOf("volume:extrusion=mesh")->rule, AccuracyRule::Exact);
    EXPECT_TRUE(MatrixVariants::variantOf("volume:extrusion=compute")->glRefusal.empty());
}

TEST(MatrixVariants, KeysAreFileNamesAndTableCells) {
    EXPECT_EQ(MatrixVariants::key("shadowmap"), "shadowmap");
    EXPECT_EQ(MatrixVariants::key("shadowmap:resolution=512:pcf=3"), "shadowmap.resolution=512.pcf=3");
    EXPECT_EQ(MatrixVariants::key("a:path=x/y|z w"), "a.path=x_y_z_w");
}

TEST(MatrixVariants, ANameSelectsItsVariantsAndASpecOneVariant) {
    EXPECT_EQ(MatrixVariants::select({"none", "auto"}), (std::vector<std::string>{"none", "auto"}));
    EXPECT_EQ(MatrixVariants::select({"raytraced"}), MatrixVariants::of("raytraced"));
    EXPECT_EQ(MatrixVariants::select({"raytraced:mode=guided"}),
              std::vector<std::string>{"raytraced:mode=guided"});
    // In the order asked, once each.
    EXPECT_EQ(
        MatrixVariants::select({"raytraced:mode=soft", "raytraced", "none"}),
        (std::vector<std::string>{"raytraced:mode=soft", "raytraced", "raytraced:mode=guided", "none"}));
    try {
        MatrixVariants::select({"raytraced:mode=hard"}); // hard is the default form, named by the name
        ADD_FAILURE() << "a spec that is no variant was taken";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ExitCode::BadInput);
        EXPECT_NE(
            std::string(e.what()).find("--technique raytraced:mode=hard: not a form the matrix renders; "
                                       "raytraced's are raytraced, raytraced:mode=soft, "
                                       "raytraced:mode=guided"),
            std::string::npos)
            << e.what();
    }
    EXPECT_THROW(MatrixVariants::select({"raytrace"}), Error); // the registry's unknown-name error
    EXPECT_THROW(MatrixVariants::variantOf("raytraced:mode=hard"), Error);
}

// ---- a variant's cells, by hand --------------------------------------------------------------------------

/// A 16x16 one-light frame, the left `shadowed` columns in shadow, judged wrong off the edge band on
/// 0.1% of the samples (inside the exact rule's 0.5%).
void paint(MatrixCell& cell, int shadowed) {
    test::paintColumns(cell, kSize, shadowed);
    CellAccuracy light;
    light.noShadowPct = 10.0;
    light.hard.wrongPct = 1.0;
    light.hard.wrongNoEdgePct = 0.1;
    cell.lights = {light};
}

/// One form's cells in GoldenMatrix::renderScene's order, of a technique with no GL form (raytraced):
/// four GL cells without a form, then Vulkan's retained and instanced, drawing `shadowed` columns.
void addCells(std::vector<MatrixCell>& cells, const std::string& form, int shadowed) {
    for (SubmitMode m :
         {SubmitMode::Retained, SubmitMode::Immediate, SubmitMode::DisplayList, SubmitMode::Instanced}) {
        MatrixCell c;
        c.technique = form;
        c.scene = kScene;
        c.mode = m;
        c.refusal = MatrixCell::Refusal::NoForm;
        c.unsupported = "no GL form";
        cells.push_back(c);
    }
    for (SubmitMode m : {SubmitMode::Retained, SubmitMode::Instanced}) {
        MatrixCell c;
        c.technique = form;
        c.scene = kScene;
        c.mode = m;
        c.api = "vulkan";
        paint(c, shadowed);
        cells.push_back(c);
    }
}

TEST(MatrixVariantCells, AVariantIsHeldToItsOwnGoldenFileAndItsDeclaredRuleUnderItsKey) {
    const std::string base = "raytraced", variant = "raytraced:mode=guided";
    std::vector<MatrixCell> cells;
    addCells(cells, base, 4);
    addCells(cells, variant, 6); // another image: each form must be held to its own golden
    const MatrixCell& baseGolden = cells[4];
    const MatrixCell& variantGolden = cells[10];
    ASSERT_EQ(GoldenMatrix::goldenCellOf(cells, cells[11]), &variantGolden);

    const std::string dir = test::freshTestDir("matrixvariants");
    EXPECT_EQ(MatrixCheck::goldenPath(dir, kScene, variant, "visibility"),
              dir + "/handmade/raytraced.mode=guided.visibility.png");
    std::map<std::string, AccuracyBound> bounds;
    for (const MatrixCell* golden : {&baseGolden, &variantGolden}) {
        for (const char* kind : {"visibility", "colour"})
            GoldenImage::write(MatrixCheck::goldenPath(dir, kScene, golden->technique, kind),
                               std::string(kind) == "colour" ? golden->colour : golden->visibility);
        const AccuracyBound b = AccuracyBounds::derive(*golden, 0);
        bounds[b.cell] = b;
    }
    const AccuracyBound guided = AccuracyBounds::derive(variantGolden, 0);
    EXPECT_EQ(guided.cell, "raytraced.mode=guided/handmade/light0");
    EXPECT_EQ(guided.rule, accuracyRuleName(MatrixVariants::variantOf(variant)->rule));
    EXPECT_NE(guided.why.find("mode=guided: " + MatrixVariants::variantOf(variant)->why), std::string::npos)
        << guided.why;
    EXPECT_EQ(AccuracyBounds::derive(baseGolden, 0).cell, "raytraced/handmade/light0");

    for (const CellVerdict& v : MatrixCheck::check(cells, dir, bounds))
        EXPECT_TRUE(v.passed()) << v.cell << "\n" << joined(v.failures);

    // The base's golden in the variant's file: the variant's cells fail against it, the base's pass.
    GoldenImage::write(MatrixCheck::goldenPath(dir, kScene, variant, "visibility"), baseGolden.visibility);
    bounds.erase("raytraced.mode=guided/handmade/light0");
    const std::vector<CellVerdict> v = MatrixCheck::check(cells, dir, bounds);
    for (size_t i = 0; i < 6; ++i) EXPECT_TRUE(v[i].passed()) << v[i].cell << "\n" << joined(v[i].failures);
    for (size_t i = 10; i < 12; ++i) {
        EXPECT_EQ(v[i].cell, variant + "/handmade/" + submitModeName(cells[i].mode) + "/vulkan");
        EXPECT_NE(joined(v[i].failures).find("visibility vs golden"), std::string::npos)
            << joined(v[i].failures);
    }
    EXPECT_NE(
        joined(v[10].failures).find("raytraced.mode=guided/handmade/light0: no committed accuracy bound"),
        std::string::npos)
        << joined(v[10].failures);
}

// Under an area light (a soft reference) a variant is judged as every technique is there: by the RMSE,
// bounded by no shadow's, its own reason added.
TEST(MatrixVariantCells, UnderAnAreaLightAVariantIsJudgedByRmse) {
    MatrixCell cell;
    cell.technique = "raytraced:mode=soft";
    cell.scene = kScene;
    cell.api = "vulkan";
    CellAccuracy light;
    light.softReference = true;
    light.noShadowRmse = 0.3;
    cell.lights = {light};
    const AccuracyBound b = AccuracyBounds::derive(cell, 0);
    EXPECT_EQ(b.cell, "raytraced.mode=soft/handmade/light0");
    EXPECT_EQ(b.metric, "rmse");
    EXPECT_DOUBLE_EQ(b.max, 0.3);
    EXPECT_NE(b.why.find("mode=soft: "), std::string::npos) << b.why;
}

} // namespace
