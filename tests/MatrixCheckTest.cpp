// The matrix's judge (bench/golden/MatrixCheck.h) and its page (bench/golden/MatrixPage.h) on cells made
// by hand, no renderer: a technique with no GL form is held to the golden and bound of its Vulkan
// retained cell and its other Vulkan cell to that cell's image; a cell the driver cannot run is neither
// passed nor unsupported but said to be not run here, its golden kept; a golden cell that refuses its
// scene must have no golden. The rendered matrix (tests/MatrixGLTest.cpp) runs the same judge on real
// cells; these cases are the ones no built-in technique has on the system driver.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "PaintedCell.h"
#include "TestSupport.h"
#include "bench/golden/AccuracyBounds.h"
#include "bench/golden/GoldenImage.h"
#include "bench/golden/GoldenMatrix.h"
#include "bench/golden/MatrixCheck.h"
#include "bench/golden/MatrixPage.h"
#include "scenes/SceneLoader.h"

using namespace sb;

namespace {

constexpr int kSize = 16;
constexpr const char* kTechnique = "vkonly"; ///< no rule of its own: held to the approximate rule
constexpr const char* kScene = "handmade";

/// A 16x16 one-light frame: the left `shadowed` columns in shadow (visibility 0), the rest lit.
void paint(MatrixCell& cell, int shadowed) {
    test::paintColumns(cell, kSize, shadowed);
    // Judged against a reference that shadows 10% of the samples; the cell is wrong on 2%.
    CellAccuracy light;
    light.noShadowPct = 10.0;
    light.hard.wrongPct = 2.0;
    cell.lights = {light};
}

MatrixCell cell(SubmitMode mode, bool vulkan, MatrixCell::Refusal refusal, const std::string& why = "") {
    MatrixCell c;
    c.technique = kTechnique;
    c.scene = kScene;
    c.mode = mode;
    c.api = vulkan ? "vulkan" : "gl";
    c.refusal = refusal;
    c.unsupported = why;
    if (refusal == MatrixCell::Refusal::None) paint(c, 4);
    return c;
}

/// The scene's cells in GoldenMatrix::renderScene's order: the four GL modes, then Vulkan's two. GL has no
/// form; the Vulkan cells are `vulkanRefusal` (None: rendered).
std::vector<MatrixCell> vulkanOnlyCells(MatrixCell::Refusal vulkanRefusal, const std::string& why = "") {
    std::vector<MatrixCell> cells;
    for (SubmitMode m :
         {SubmitMode::Retained, SubmitMode::Immediate, SubmitMode::DisplayList, SubmitMode::Instanced})
        cells.push_back(cell(m, false, MatrixCell::Refusal::NoForm, "vkonly has no GL form: no ray queries"));
    for (SubmitMode m : {SubmitMode::Retained, SubmitMode::Instanced})
        cells.push_back(cell(m, true, vulkanRefusal, why));
    return cells;
}

/// A golden folder holding the technique's golden as the Vulkan retained cell draws it.
std::string goldenDir(const MatrixCell& golden) {
    const std::string dir = test::freshTestDir("matrixcheck");
    GoldenImage::write(MatrixCheck::goldenPath(dir, kScene, kTechnique, "visibility"), golden.visibility);
    GoldenImage::write(MatrixCheck::goldenPath(dir, kScene, kTechnique, "colour"), golden.colour);
    return dir;
}

std::map<std::string, AccuracyBound> committedBound() {
    AccuracyBound b;
    b.cell = std::string(kTechnique) + "/" + kScene + "/light0";
    b.metric = "wrong_pct";
    b.max = 10.0;
    b.rule = "approximate";
    return {{b.cell, b}};
}

std::string joined(const std::vector<std::string>& lines) {
    std::string out;
    for (const std::string& l : lines) out += l + "\n";
    return out;
}

TEST(MatrixCheckVulkanOnly, TheVulkanRetainedCellIsTheGoldenCell) {
    const std::vector<MatrixCell> cells = vulkanOnlyCells(MatrixCell::Refusal::None);
    EXPECT_EQ(GoldenMatrix::goldenCellOf(cells, cells[0]), &cells[4]);
    EXPECT_EQ(GoldenMatrix::goldenCellOf(cells, cells[5]), &cells[4]);
    // A technique with a GL form keeps its GL retained cell, whatever its Vulkan cells are.
    std::vector<MatrixCell> both = cells;
    for (size_t i = 0; i < 4; ++i) both[i] = cell(cells[i].mode, false, MatrixCell::Refusal::None);
    EXPECT_EQ(GoldenMatrix::goldenCellOf(both, both[4]), &both[0]);
}

TEST(MatrixCheckVulkanOnly, GoldenBoundAndTheOtherModeAreJudgedFromVulkanRetained) {
    const std::vector<MatrixCell> cells = vulkanOnlyCells(MatrixCell::Refusal::None);
    const std::vector<CellVerdict> v = MatrixCheck::check(cells, goldenDir(cells[4]), committedBound());
    ASSERT_EQ(v.size(), 6u);
    for (size_t i = 0; i < 4; ++i) {
        EXPECT_TRUE(v[i].passed()) << v[i].cell << "\n" << joined(v[i].failures);
        EXPECT_NE(v[i].unsupported.find("no GL form"), std::string::npos) << v[i].cell;
        EXPECT_EQ(v[i].notRun, "") << v[i].cell;
    }
    for (size_t i = 4; i < 6; ++i) {
        EXPECT_TRUE(v[i].passed()) << v[i].cell << "\n" << joined(v[i].failures);
        const std::string details = joined(v[i].details);
        EXPECT_NE(details.find("visibility vs golden"), std::string::npos) << details;
        EXPECT_NE(details.find("vkonly/handmade/light0 wrong_pct 2 (bound 0..10"), std::string::npos)
            << details;
    }
    EXPECT_NE(joined(v[5].details).find("visibility vs Vulkan retained"), std::string::npos);
    EXPECT_EQ(joined(v[4].details).find("vs Vulkan retained"), std::string::npos); // not against itself
}

TEST(MatrixCheckVulkanOnly, AChangedModeAChangedGoldenAndAMissingBoundFail) {
    std::vector<MatrixCell> cells = vulkanOnlyCells(MatrixCell::Refusal::None);
    const std::string dir = goldenDir(cells[4]);
    paint(cells[5], 5); // instanced shadows one column more: 16 of 256 samples (6%) differ
    paint(cells[4], 6); // retained: two columns more than its golden
    const std::vector<CellVerdict> v = MatrixCheck::check(cells, dir, {});
    EXPECT_NE(joined(v[5].failures).find("visibility vs Vulkan retained"), std::string::npos)
        << joined(v[5].failures);
    EXPECT_NE(joined(v[4].failures).find("visibility vs golden"), std::string::npos) << joined(v[4].failures);
    EXPECT_NE(joined(v[4].failures).find("no committed accuracy bound"), std::string::npos)
        << joined(v[4].failures);
    for (size_t i = 0; i < 4; ++i) EXPECT_TRUE(v[i].passed()) << v[i].cell << "\n" << joined(v[i].failures);
}

TEST(MatrixCheckVulkanOnly, CellsThisDriverCannotRunAreSaidNotRunAndKeepTheirGolden) {
    const std::string why = "not on the driver system: vkonly needs VK_KHR_ray_query (not available on "
                            "llvmpipe, Vulkan 1.3.230)";
    const std::vector<MatrixCell> rendered = vulkanOnlyCells(MatrixCell::Refusal::None);
    const std::vector<MatrixCell> cells = vulkanOnlyCells(MatrixCell::Refusal::Driver, why);
    const std::vector<CellVerdict> v = MatrixCheck::check(cells, goldenDir(rendered[4]), committedBound());
    for (size_t i = 4; i < 6; ++i) {
        EXPECT_TRUE(v[i].passed()) << v[i].cell << "\n" << joined(v[i].failures);
        EXPECT_EQ(v[i].notRun, why) << v[i].cell;
        EXPECT_EQ(v[i].unsupported, "") << v[i].cell;   // not a refusal of the technique's
        EXPECT_TRUE(v[i].details.empty()) << v[i].cell; // nothing judged
    }
}

TEST(MatrixCheckVulkanOnly, AVulkanGoldenCellRefusingItsSceneMustHaveNoGolden) {
    const std::vector<MatrixCell> rendered = vulkanOnlyCells(MatrixCell::Refusal::None);
    const std::vector<MatrixCell> cells =
        vulkanOnlyCells(MatrixCell::Refusal::Scene, "vkonly: light 0 is an area light");
    const std::vector<CellVerdict> v = MatrixCheck::check(cells, goldenDir(rendered[4]), committedBound());
    EXPECT_NE(joined(v[4].failures).find("refuses the scene but has a golden"), std::string::npos)
        << joined(v[4].failures);
    EXPECT_TRUE(v[5].passed()) << joined(v[5].failures); // the golden is the golden cell's to answer for
    const std::vector<CellVerdict> clean = MatrixCheck::check(cells, test::freshTestDir("nogolden"), {});
    for (const CellVerdict& c : clean) EXPECT_TRUE(c.passed()) << c.cell << "\n" << joined(c.failures);
}

// The page keeps the rows and exceptions an update did not render, in the matrix's order, and drops rows
// of scenes or techniques that are gone.
TEST(MatrixPage, AnUpdateOfSomeRowsKeepsTheOthersInOrder) {
    const std::string dir = test::freshTestDir("matrixpage");
    test::writeFile(dir + "/MATRIX.md",
                    "# old header\n\nold text\n\n| technique | scene | modes | accuracy |\n"
                    "|---|---|---|---|\n"
                    "| b | s1 | 4/4 pass | old b s1 |\n"
                    "| a | s2 | 4/4 pass | old a s2 |\n"
                    "| gone | s1 | 4/4 pass | removed technique |\n"
                    "| a | s1 | 4/4 pass | old a s1 |\n"
                    "\n## Exceptions\n\n"
                    "- `b/s1/light0`: b's old exception\n"
                    "- `a/s2/light1`: a's exception on s2\n");
    MatrixPage page = MatrixPage::read(dir + "/MATRIX.md");
    EXPECT_TRUE(page.has("a", "s1"));
    EXPECT_FALSE(page.has("a", "s3"));
    page.set("b", "s1", "| b | s1 | no GL form (why); Vulkan 2/2 pass on the driver mesa-25.0.7 | new |", {});
    const std::string text = page.text(128, {"s1", "s2"}, {"a", "b"});
    const std::string rows = text.substr(text.find("|---|---|---|---|\n") + 18);
    EXPECT_EQ(rows, "| a | s1 | 4/4 pass | old a s1 |\n"
                    "| b | s1 | no GL form (why); Vulkan 2/2 pass on the driver mesa-25.0.7 | new |\n"
                    "| a | s2 | 4/4 pass | old a s2 |\n"
                    "\n## Exceptions\n\n"
                    "- `a/s2/light1`: a's exception on s2\n");
    EXPECT_NE(text.find("at 128x128"), std::string::npos);
    EXPECT_EQ(text.find("old header"), std::string::npos);
}

} // namespace

namespace {

// The matrix draws the heavy scenes with fewer layout instances (MatrixOptions::maxTriangles). Hand
// count: aircraft holds a 512-triangle ground and 200 aircraft of 2624 triangles, so (262144 - 512) /
// 2624 = 99.7 keeps 99; teapot a 512-triangle ground and 200 teapots of 4096: 63.9 keeps 63;
// synthetic_triangles 256 spheres of 3968 and nothing else: 66.06 keeps 66. A scene under the budget
// (city) keeps its own, and every cut scene lands at most one instance under the budget.
TEST(MatrixScenes, HeavyScenesDrawTheirLayoutCutToTheTriangleBudget) {
    const MatrixOptions options;
    ASSERT_EQ(options.maxTriangles, size_t(262144));
    const std::map<std::string, uint32_t> expected = {
        {"aircraft", 99}, {"teapot", 63}, {"synthetic_triangles", 66}};
    for (const auto& [name, count] : expected) {
        const std::optional<uint32_t> n = GoldenMatrix::layoutInstances(SceneLoader::load(name), options);
        ASSERT_TRUE(n.has_value()) << name;
        EXPECT_EQ(*n, count) << name;
        SceneOptions cut;
        cut.instances = *n;
        const Scene drawn = SceneLoader::load(name, cut);
        EXPECT_LE(drawn.totalTriangles(), options.maxTriangles) << name;
        cut.instances = *n + 1;
        EXPECT_GT(SceneLoader::load(name, cut).totalTriangles(), options.maxTriangles) << name;
    }
    EXPECT_FALSE(GoldenMatrix::layoutInstances(SceneLoader::load("city"), options).has_value());
}

} // namespace
