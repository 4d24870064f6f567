// Effect requests through the bench binary (techniques/EffectCoverage.h, bench/explain/ExplainCommand.h): a
// technique short of an effect the scene asks for is measured with one warning line and says so in its
// row; --strict-effects refuses it (exit 3, a row with status unsupported) while the others are measured;
// baselines never warn; `bench explain` prints the same masks and the passes of one frame. The expected
// masks follow from the scene files (aircraft asks for hard_shadows and self_shadowing, sphere_plane for
// hard_shadows) and the techniques' headers (planar cannot self-shadow); the expected draw and triangle
// counts of explain are counted here from the scene as loaded, not from bench's census.
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/output/ResultColumns.h"
#include "scenes/SceneLoader.h"

using namespace sb;
using test::runCommand;

namespace {

const std::string kBench = SB_BENCH_BINARY;
const std::string kQuick = " --size 64x64 --frames 2 --warmup 0 --no-timer-check -n 3";
const std::string kPlanarWarning =
    "bench: warning: planar cannot produce self_shadowing, which scene aircraft asks for; measured anyway";

size_t occurrences(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

} // namespace

TEST(EffectsCli, ShortTechniqueIsMeasuredWithOneWarningAndItsRowSaysWhatIsMissing) {
    const std::string csv = test::freshTestDir("effects") + "/r.csv";
    const auto r = runCommand(kBench + " -t planar -t shadowmap -t none --repeat 2 --csv " + csv + kQuick);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    // One line for planar over both rounds; none for shadowmap (it self-shadows) or none (a baseline).
    EXPECT_EQ(occurrences(r.output, "bench: warning:"), 1u) << r.output;
    EXPECT_NE(r.output.find(kPlanarWarning), std::string::npos) << r.output;
    const auto rows = test::csvRowMaps(csv);
    ASSERT_EQ(rows.size(), 6u);
    for (const auto& row : rows) {
        EXPECT_EQ(row.at(col::kStatus), "ok");
        EXPECT_EQ(row.at(col::kEffectsRequested), "hard_shadows+self_shadowing");
        const std::string& t = row.at(col::kTechnique);
        const std::string delivered = t == "none"     ? "none"
                                      : t == "planar" ? "hard_shadows"
                                                      : "hard_shadows+self_shadowing";
        const std::string missing = t == "none"     ? "hard_shadows+self_shadowing"
                                    : t == "planar" ? "self_shadowing"
                                                    : "none";
        EXPECT_EQ(row.at(col::kEffectsDelivered), delivered) << t;
        EXPECT_EQ(row.at(col::kEffectsMissing), missing) << t;
    }
}

TEST(EffectsCli, StrictEffectsRefusesTheShortTechniqueAndMeasuresTheRest) {
    const std::string csv = test::freshTestDir("effects") + "/r.csv";
    const auto r = runCommand(kBench + " -t planar -t shadowmap --strict-effects --csv " + csv + kQuick);
    EXPECT_EQ(r.exitCode, 3) << r.output;
    EXPECT_EQ(r.output.find("bench: warning:"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(
                  "planar cannot produce self_shadowing, which scene aircraft asks for (--strict-effects)"),
              std::string::npos)
        << r.output;
    const auto rows = test::csvRowMaps(csv);
    ASSERT_EQ(rows.size(), 2u) << r.output;
    std::map<std::string, std::map<std::string, std::string>> by;
    for (const auto& row : rows) by[row.at(col::kTechnique)] = row;
    EXPECT_EQ(by.at("planar").at(col::kStatus), "unsupported");
    EXPECT_EQ(by.at("planar").at(col::kEffectsMissing), "self_shadowing");
    EXPECT_EQ(by.at("shadowmap").at(col::kStatus), "ok");

    // Alone, the refused technique leaves nothing measured: exit 3 and no row (an existing CSV keeps
    // its rows byte for byte).
    const std::string before = test::readFile(csv);
    const auto alone = runCommand(kBench + " -t planar --strict-effects --csv " + csv + kQuick);
    EXPECT_EQ(alone.exitCode, 3) << alone.output;
    EXPECT_EQ(test::readFile(csv), before);

    // A scene that asks for what planar delivers is measured under --strict-effects.
    const auto fine = runCommand(kBench + " -t planar --strict-effects --scene sphere_plane --size 64x64 "
                                          "--frames 2 --warmup 0 --no-timer-check");
    EXPECT_EQ(fine.exitCode, 0) << fine.output;
}

TEST(EffectsCli, ExplainPrintsTheMasksPermutationAndPassesOfOneFrame) {
    // sphere_plane: the sphere casts, the ground does not (its file says casts_shadow false); every
    // instance is lit. So shadowmap's depth pass draws the sphere alone and its lighting pass both.
    const Scene scene = SceneLoader::load("sphere_plane");
    size_t casters = 0, casterTriangles = 0, allTriangles = 0;
    for (const Instance& i : scene.instances) {
        const size_t tris = scene.meshes[i.mesh].triangleCount();
        allTriangles += tris;
        if (i.castsShadow) casterTriangles += tris, ++casters;
    }
    ASSERT_EQ(casters, 1u);
    const auto r = runCommand(
        kBench + " explain -t shadowmap -t planar -t vsm:blur=0 -t none --scene sphere_plane --size 64x64");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("scene sphere_plane: 1 light(s), " + std::to_string(allTriangles) + " triangles"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("effects requested  hard_shadows\n"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(
                  "permutation        "
                  "|HW_COMPARE,LIGHT_COUNT,PCF_SIZE,SB_AMBIENT=vec3(0.15),SB_LIGHT_COLORS=#53566dcb9c73b8ff,"
                  "SB_LIGHT_CONES=#45f3d0dc922a31db,SB_POSITIONAL_LIGHTS=0u,SB_RANGED_LIGHTS=0u,"
                  "SB_SPOT_LIGHTS=0u,SB_STATIC_LIGHTS,SHADOW_MAP"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("depth     ran  1 draws, " + std::to_string(casterTriangles) + " triangles"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("lighting  ran  2 draws, " + std::to_string(allTriangles) + " triangles"),
              std::string::npos)
        << r.output;
    // vsm with blur 0 leaves its blur pass out and says why (PassTimer::skip).
    EXPECT_NE(r.output.find("blur      skipped  blur below 2 texels: a one-tap kernel"), std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("blur      ran"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("cannot deliver     hard_shadows  (a baseline: it draws no shadow by design)"),
              std::string::npos)
        << r.output;
}

TEST(EffectsCli, ExplainSaysWhatIsMissingAndWhyATechniqueIsRefused) {
    const auto r = runCommand(kBench + " explain -t planar -n 3 --size 64x64");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("effects requested  hard_shadows+self_shadowing"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("effects delivered  hard_shadows\n"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("cannot deliver     self_shadowing  (a run warns; --strict-effects refuses it)"),
              std::string::npos)
        << r.output;
    // shadowmap refuses a point light: explained, with the refusal's exit code as the command's.
    const auto refused =
        runCommand(kBench + " explain -t none -t shadowmap --scene point_light --size 64x64");
    EXPECT_EQ(refused.exitCode, 3) << refused.output;
    EXPECT_NE(refused.output.find("refused            shadowmap: light 0 is a point light"),
              std::string::npos)
        << refused.output;
    EXPECT_NE(refused.output.find("lighting  ran"), std::string::npos) << "none is still explained\n"
                                                                       << refused.output;
    // Its --help is explain's own, with examples.
    const auto help = runCommand(kBench + " explain --help");
    EXPECT_EQ(help.exitCode, 0) << help.output;
    EXPECT_NE(help.output.find("bench explain [options]: the options of a run"), std::string::npos)
        << help.output;
    EXPECT_NE(help.output.find("  bench explain -t planar --scene aircraft"), std::string::npos)
        << help.output;
    // A typo is bad input before any GL.
    EXPECT_EQ(runCommand(kBench + " explain -t shadowmapp").exitCode, 2);
    // -t auto is a timed choice that explain does not make: bad input, saying what to run instead.
    const auto autoRun = runCommand(kBench + " explain -t auto");
    EXPECT_EQ(autoRun.exitCode, 2) << autoRun.output;
    EXPECT_NE(autoRun.output.find("bench explain does not take -t auto"), std::string::npos)
        << autoRun.output;
}
