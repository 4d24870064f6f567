// `occluder`, and `hybrid` whose default self-shadow part it is, under both SIMD widths llvmpipe runs:
// 128 bits (CPUs without AVX, ARM) and 256 bits (this CI machine's default). llvmpipe keys its on-disk
// shader cache by the CPU's features, not by LP_NATIVE_VECTOR_WIDTH, so a 128-bit run after a run at
// the default width loaded the other width's machine code and aborted with heap corruption in the
// driver (core/DriverShaderCache.h keeps a cache per width). The runs share one fresh cache folder, the
// default-width run first, as on a machine where both were ever run.
//
// The outcome: every run exits 0 and each width draws the default run's visibility. Tolerance: one 8-bit
// step per channel (the visibility target is stored as 8 bits; a value at a rounding boundary may round
// the other way if the two widths' code contracts a multiply-add differently), no pixel beyond it;
// measured on llvmpipe 22.3.6 (LLVM 15): bit-identical. The planes must shadow something (at least 8
// pixels darker than half, measured 15), so equal images are not two unshadowed ones.
#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "PngDecoder.h"
#include "TestPaths.h"
#include "TestSupport.h"

using namespace sb;

namespace {

constexpr const char* kTechniques[] = {"occluder", "hybrid"};

/// One aircraft (its three built-in planes) over the aircraft scene's ground, under a steep light, seen
/// from the side: its wings and fins shadow the fuselage (the built-in scenes' aircraft are too small in
/// a 64x64 frame to show it). At tessellation 8, or without the ground, the 128-bit run after a default
/// one did not abort on the shared cache: the test needs the meshes this size.
std::string writeScene(const std::string& dir) {
    const std::string path = dir + "/aircraft.json";
    test::writeFile(path, R"({"name": "occluder_width",
  "meshes": [{"name": "f35", "generator": "aircraft", "tessellation": 16},
             {"name": "ground", "generator": "plane", "size": 200, "tessellation": 16}],
  "instances": [{"mesh": "f35", "position": [0, 0, 0]},
                {"mesh": "ground", "position": [0, -1, 0], "casts_shadow": false}],
  "lights": [{"type": "directional", "direction": [0.2, -1, 0.1]}],
  "cameras": [{"name": "side", "eye": [3, 2.5, 4], "target": [0, 0, 0], "fov": 45, "near": 0.05, "far": 50}],
  "effects": ["hard_shadows", "self_shadowing"]})");
    return path;
}

/// Runs the techniques at 64x64, one frame, with the given LP_NATIVE_VECTOR_WIDTH ("" = unset) and the
/// shared cache folder, writing `<stem>_<technique>.png` visibility images.
test::CommandResult run(const std::string& scene, const std::string& cache, const std::string& width,
                        const std::string& stem) {
    std::string command = "env -u LP_NATIVE_VECTOR_WIDTH MESA_SHADER_CACHE_DIR='" + cache + "' ";
    if (!width.empty()) command += "LP_NATIVE_VECTOR_WIDTH=" + width + " ";
    command += std::string("'") + test::benchBinary() + "'";
    for (const char* t : kTechniques) command += std::string(" -t ") + t;
    return test::runCommand(command + " --scene '" + scene +
                            "' --camera side --size 64x64 --frames 1 --no-timer-check --visibility '" + stem +
                            ".png'");
}

/// Largest per-channel difference of two decoded images of the same size.
int maxDifference(const test::DecodedPng& a, const test::DecodedPng& b) {
    int worst = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) worst = std::max(worst, std::abs(a.pixels[i] - b.pixels[i]));
    return worst;
}

/// Pixels whose first channel (light 0's visibility) is below half.
size_t shadowedPixels(const test::DecodedPng& png) {
    size_t dark = 0;
    for (size_t p = 0; p < size_t(png.width) * size_t(png.height); ++p)
        dark += png.pixels[p * size_t(png.channels)] < 128 ? 1 : 0;
    return dark;
}

TEST(OccluderVectorWidthCliTest, BothWidthsRunAndDrawTheSameVisibility) {
    const std::string dir = test::freshTestDir("occluder-width");
    const std::string cache = dir + "/cache", scene = writeScene(dir);
    const test::CommandResult first = run(scene, cache, "", dir + "/default");
    ASSERT_EQ(first.exitCode, 0) << first.output;
    for (const char* width : {"128", "256"}) {
        SCOPED_TRACE(std::string("LP_NATIVE_VECTOR_WIDTH=") + width);
        const test::CommandResult r = run(scene, cache, width, dir + "/w" + width);
        ASSERT_EQ(r.exitCode, 0) << r.output;
        // Every x86-64 and ARM CPU runs 128 bits when asked (the renderer string names the width).
        const bool narrow = std::string(width) == "128";
        EXPECT_TRUE(!narrow || r.output.find("128 bits") != std::string::npos) << r.output;
        for (const char* t : kTechniques) {
            SCOPED_TRACE(t);
            const test::DecodedPng expected = test::decodePng(dir + "/default_" + t + ".png");
            const test::DecodedPng got = test::decodePng(dir + "/w" + width + "_" + t + ".png");
            ASSERT_TRUE(expected.ok && got.ok) << expected.why << got.why;
            ASSERT_EQ(got.width, expected.width);
            ASSERT_EQ(got.height, expected.height);
            ASSERT_EQ(got.channels, expected.channels);
            EXPECT_LE(maxDifference(got, expected), 1);
            std::cout << t << " at " << width << " bits: " << shadowedPixels(got) << " pixels shadowed\n";
            EXPECT_GE(shadowedPixels(got), 8u) << "the planes shadow the fuselage (measured: 15 pixels)";
        }
    }
}

} // namespace
