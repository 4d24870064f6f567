// The light fit as a knob, end to end (scenes/LightFit.h, techniques/LightFitProperties.h): every flat
// map takes `fit`, and counter_map_covered_pct reports what it framed. On sphere_plane (a sphere of
// radius 1, tessellation 32, under an oblique directional light) the sphere fit frames a square of side
// 2 sqrt(3) x 1.02 + 2e-3 from any direction, so the share the sphere covers is its silhouette over that
// square's area, worked out by hand as in tests/LightFitTest.cpp; the other fits order around it; the
// depth pass's fragments fall with the share; and GL and Vulkan report the same count (one home:
// scenes/MapCoverage.h).
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/output/ResultColumns.h"

using namespace sb;

namespace {

const std::string kBench = SB_BENCH_BINARY;
constexpr double kPi = 3.14159265358979323846;
// One census frame is all the counters need; the timer check is not part of what is tested.
const std::string kArgs = " --scene sphere_plane --size 64x64 --frames 1 --warmup 0 --no-timer-check";

double number(const std::map<std::string, std::string>& row, const std::string& column) {
    const auto it = row.find(column);
    EXPECT_NE(it, row.end()) << column;
    return it == row.end() || it->second.empty() ? -1.0 : std::stod(it->second);
}

std::vector<std::map<std::string, std::string>> run(const std::string& api, const std::string& techniques,
                                                    int& exitCode, std::string& output) {
    const std::string dir = test::freshTestDir("light-fit-" + api);
    const auto r =
        test::runCommand(kBench + " --api " + api + kArgs + techniques + " --csv " + dir + "/r.csv");
    exitCode = r.exitCode;
    output = r.output;
    return r.exitCode == 0 ? test::csvRowMaps(dir + "/r.csv")
                           : std::vector<std::map<std::string, std::string>>{};
}

} // namespace

TEST(LightFitCli, EachFitFramesTheSphereAndTheCounterSaysHowMuch) {
    int rc = 0;
    std::string out;
    const auto rows =
        run("gl",
            " -t shadowmap:resolution=1024 -t shadowmap:resolution=1024:fit=sphere"
            " -t shadowmap:resolution=1024:fit=scene -t pcss:resolution=1024:fit=sphere"
            " -t vsm:resolution=1024:fit=sphere:blur=0 -t esm:resolution=1024:fit=sphere:blur=0",
            rc, out);
    ASSERT_EQ(rc, 0) << out;
    ASSERT_EQ(rows.size(), 6u);
    const std::string covered = col::member(col::kCounter, "map_covered_pct");
    // The sphere fit: the silhouette lies between the discs of the tessellated sphere's inradius
    // (cos(sqrt(2) pi / 64), tests/LightFitTest.cpp) and of radius 1; counting texel centres adds at
    // most the texels the outline meets, 4 x its 2-unit width in texels + 4.
    const double side = 2.0 * std::sqrt(3.0) * 1.02 + 2e-3, texels = 1024.0 / side;
    const double inradius = std::cos(std::sqrt(2.0) * kPi / 64.0);
    const double slack = 100.0 * (4.0 * 2.0 * texels + 4.0) / (1024.0 * 1024.0);
    const double lo = 100.0 * kPi * inradius * inradius / (side * side) - slack;
    const double hi = 100.0 * kPi / (side * side) + slack;
    const double sphere = number(rows[1], covered);
    EXPECT_GE(sphere, lo);
    EXPECT_LE(sphere, hi);
    // pcss frames its map as shadowmap does: the same count exactly.
    EXPECT_EQ(number(rows[3], covered), sphere);
    // vsm and esm widen the fit by their blur's border (blur 0: 0 / 2 + 1 = 1 texel each side), so the
    // sphere keeps (1022 / 1024)^2 of the share, again within the counting's slack.
    for (size_t i : {4u, 5u}) {
        SCOPED_TRACE(rows[i].at(col::kTechnique));
        EXPECT_NEAR(number(rows[i], covered), sphere * (1022.0 / 1024.0) * (1022.0 / 1024.0), 2.0 * slack);
    }
    // The casters' box is tighter than the sphere's square (more of the map covered), the scene's 40 x 40
    // ground far looser (about (3.53 / 40.8)^2 of the sphere's share).
    const double casters = number(rows[0], covered), scene = number(rows[2], covered);
    EXPECT_GT(casters, sphere);
    EXPECT_LT(scene, sphere * 0.01);
    EXPECT_GT(scene, 0.0);
    // The cost side: the depth pass shades fewer fragments as the casters cover fewer texels.
    const std::string fragments = col::member(col::kWorkFragments, "depth");
    if (!rows[0].at(fragments).empty()) {
        EXPECT_GT(number(rows[0], fragments), number(rows[1], fragments));
        EXPECT_GT(number(rows[1], fragments), number(rows[2], fragments));
    }
}

TEST(LightFitCli, VulkanCountsWhatGlCounts) {
    const std::string techniques = " -t shadowmap:resolution=512:fit=sphere -t vsm:resolution=512:fit=scene";
    int rcGl = 0, rcVk = 0;
    std::string outGl, outVk;
    const auto gl = run("gl", techniques, rcGl, outGl);
    ASSERT_EQ(rcGl, 0) << outGl;
    const auto vk = run("vulkan", techniques, rcVk, outVk);
    if (rcVk == 3) GTEST_SKIP() << "no Vulkan device here: " << outVk;
    ASSERT_EQ(rcVk, 0) << outVk;
    ASSERT_EQ(gl.size(), 2u);
    ASSERT_EQ(vk.size(), 2u);
    const std::string covered = col::member(col::kCounter, "map_covered_pct");
    for (size_t i = 0; i < 2; ++i) {
        SCOPED_TRACE(gl[i].at(col::kTechnique));
        EXPECT_GT(number(gl[i], covered), 0.0);
        EXPECT_EQ(gl[i].at(covered), vk[i].at(covered));
    }
}
