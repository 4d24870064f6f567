// The `handshadow` binary (bench/handwritten/handshadow/) end to end: it runs two frames at a small size,
// prints its medians, and its image shows the shadow where the scene's closed form puts it and where bench's
// own `shadowmap` draws it. The comparison with bench is what makes handshadow's timings worth anything: a
// hand program that drew less (no shadow, a wrong light camera) would look faster for the wrong reason.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/golden/GoldenImage.h"
#include "bench/golden/ImageDiff.h"

using namespace sb;
using test::runCommand;

namespace {

constexpr int kSize = 128;
// sphere_plane from "top": a sphere of radius 1 at (0, 3, 0) over y = 0, light along (0.3, -1, 0.2);
// the eye at (0, 30, 0) with a 20 degree fov sees 30 tan(10 deg) = 5.29 units either side, +X to the
// right and +Z downwards in the image (scenes/data/sphere_plane.json).
constexpr double kHalfExtent = 5.2898;
// (1.4, 0, 0.93): 0.6 units from the shadow ellipse's centre (0.9, 0, 0.6) along its major axis
// (semi-major 1.063), so well inside it, and 20 px from the image centre, outside the sphere's own
// disc (radius 13.4 px at 128^2). (-3, 0, -3): open ground, far from the shadow.
constexpr double kShadowX = 1.4, kShadowZ = 0.933, kLitX = -3.0, kLitZ = -3.0;

int column(double x) {
    return int(std::floor((x / kHalfExtent + 1.0) * 0.5 * kSize));
}
int row(double z) {
    return int(std::floor((z / kHalfExtent + 1.0) * 0.5 * kSize));
}
int luminance(const Image8& im, int col, int r) {
    const uint8_t* p = &im.pixels[(size_t(r) * size_t(im.width) + size_t(col)) * size_t(im.channels)];
    return (int(p[0]) + int(p[1]) + int(p[2])) / 3;
}
// Dark = the ground in shadow: 0.8 albedo x 0.15 ambient = 31/255, against 0.8 x (0.15 + 0.96) = 226
// lit; 80 splits the two with room for the bilinear compare's edge pixels either way.
size_t darkPixels(const Image8& im) {
    size_t n = 0;
    for (int r = 0; r < im.height; ++r)
        for (int c = 0; c < im.width; ++c) n += luminance(im, c, r) < 80 ? 1 : 0;
    return n;
}

} // namespace

TEST(HandShadowCli, RunsTwoFramesAndShadowsWhereBenchDoes) {
    const std::string dir = test::freshTestDir("handshadow");
    const std::string scene = " --scene sphere_plane --camera top --size 128x128";
    const std::string handPng = dir + "/hand.png", benchPng = dir + "/bench.png";

    const test::CommandResult hand = runCommand(std::string(SB_HANDSHADOW_BINARY) + scene +
                                                " --map-size 256 --frames 2 --warmup 0 --png " + handPng);
    ASSERT_EQ(hand.exitCode, 0) << hand.output;
    EXPECT_NE(hand.output.find("csv,handshadow,sphere_plane,128,128,256,"), std::string::npos) << hand.output;
    EXPECT_NE(hand.output.find("cpu submit median"), std::string::npos) << hand.output;

    const test::CommandResult bench =
        runCommand(std::string(SB_BENCH_BINARY) + " -t shadowmap:resolution=256" + scene +
                   " --frames 1 --warmup 0 --no-timer-check -q --screenshot " + benchPng);
    ASSERT_EQ(bench.exitCode, 0) << bench.output;

    const Image8 h = GoldenImage::read(handPng), b = GoldenImage::read(benchPng);
    ASSERT_EQ(h.width, kSize);
    ASSERT_EQ(h.height, kSize);
    ASSERT_GE(h.channels, 3);

    // The closed form: inside the ellipse dark, open ground lit (GoldenImage rows are top first).
    EXPECT_LT(luminance(h, column(kShadowX), row(kShadowZ)), 80) << "no shadow inside the ellipse";
    EXPECT_GT(luminance(h, column(kLitX), row(kLitZ)), 180) << "open ground not lit";

    // Against bench's image of the same frame: the shadowed area within 20 % (the visible part of the
    // ellipse is about 250 px; both use the same light camera and bilinear compare, so only edge pixels
    // may differ), and at most 2 % of all pixels more than 16/255 apart in some channel.
    const size_t darkHand = darkPixels(h), darkBench = darkPixels(b);
    ASSERT_GT(darkBench, 100u) << "bench's own image shows no shadow";
    EXPECT_GT(double(darkHand), 0.8 * double(darkBench)) << darkHand << " vs " << darkBench;
    EXPECT_LT(double(darkHand), 1.25 * double(darkBench)) << darkHand << " vs " << darkBench;
    const DiffTolerance tolerance{16, 0.02};
    const ImageDiffResult diff = ImageDiff::compare(b, h, tolerance);
    EXPECT_TRUE(diff.passes(tolerance)) << diff.describe(tolerance);

    // --harness-targets adds bench's visibility target and stencil; the colour image must not change
    // (1/255 for the float path's rounding; no pixel may move more).
    const std::string harnessPng = dir + "/hand-harness-targets.png";
    const test::CommandResult harness =
        runCommand(std::string(SB_HANDSHADOW_BINARY) + scene +
                   " --map-size 256 --frames 2 --warmup 0 --harness-targets --png " + harnessPng);
    ASSERT_EQ(harness.exitCode, 0) << harness.output;
    EXPECT_NE(harness.output.find(",harness_targets"), std::string::npos) << harness.output;
    const DiffTolerance same{1, 0.0};
    const ImageDiffResult sameDiff = ImageDiff::compare(h, GoldenImage::read(harnessPng), same);
    EXPECT_TRUE(sameDiff.passes(same)) << sameDiff.describe(same);
    std::filesystem::remove_all(dir);
}

TEST(HandShadowCli, RefusesAnUnknownOptionAsBadInput) {
    const test::CommandResult r = runCommand(std::string(SB_HANDSHADOW_BINARY) + " --frobnicate 3");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--frobnicate"), std::string::npos) << r.output;
}
