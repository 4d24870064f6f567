// apitrace, a real GL debugging client no one here wrote, end to end on every registered technique:
// the plain `apitrace trace bench ...` records a short run, eglretrace replays it headless
// (WAFFLE_PLATFORM=surfaceless_egl: waffle's platform switch of the replayer, not of the traced run),
// and the replayed colour target at the read-back that wrote --screenshot must equal the screenshot.
// Tolerance: zero, bit-identical. The replay issues the same GL calls with the same data on the same
// driver and machine, and Mesa renders deterministically, so any difference is a call the trace lost
// (before the EGL backends handed the GLX tracer over, the trace had no context at all and the replay
// drew nothing: "no current context").
#include <array>
#include <filesystem>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "PngDecoder.h"
#include "TestSupport.h"
#include "gl/backends/ApitraceHandoff.h"
#include "registry/TechniqueRegistry.h"

using namespace sb;
using test::runCommand;

namespace {

constexpr int kSize = 64;

struct Rgb8 {
    int width = 0, height = 0;
    std::vector<unsigned char> pixels; ///< 3 channels, top row first
};

/// An 8-bit image as RGB (alpha dropped); width 0 when it cannot be read.
Rgb8 readRgb(const std::string& path) {
    Rgb8 image;
    const test::DecodedPng png = test::decodePng(path);
    if (!png.ok) return image;
    const size_t channels = size_t(png.channels);
    image.width = png.width;
    image.height = png.height;
    image.pixels.resize(size_t(png.width) * size_t(png.height) * 3);
    for (size_t p = 0; p < size_t(png.width) * size_t(png.height); ++p)
        for (size_t c = 0; c < 3; ++c)
            image.pixels[p * 3 + c] = png.pixels[p * channels + std::min(c, channels - 1)];
    return image;
}

/// Call number of the last colour read-back (glReadPixels of the whole kSize x kSize target as RGBA8:
/// ImageWriter::writeColor's read) in `apitrace dump` output; -1 when there is none.
long lastColorReadback(const std::string& dump) {
    const std::regex call(
        "(^|\n)([0-9]+) (@[0-9]+ )?glReadPixels\\(x = 0, y = 0, width = " + std::to_string(kSize) +
        ", height = " + std::to_string(kSize) + ", format = GL_RGBA, type = GL_UNSIGNED_BYTE");
    long last = -1;
    for (auto it = std::sregex_iterator(dump.begin(), dump.end(), call); it != std::sregex_iterator(); ++it)
        last = std::stol((*it)[2]);
    return last;
}

/// apitrace's own tools are what is under test: a machine without them fails (never skips) naming
/// the package, so a missing install cannot pass as "traceable".
void requireApitrace() {
    for (const char* tool : {"apitrace", "eglretrace"}) {
        auto r = runCommand(std::string("command -v ") + tool);
        ASSERT_EQ(r.exitCode, 0) << tool << " not found: install the Debian package `apitrace` "
                                 << "(scripts/install-deps.sh installs it)";
    }
}

class Apitrace : public ::testing::TestWithParam<std::string> {};

TEST_P(Apitrace, PlainTraceReplaysToTheScreenshot) {
    requireApitrace();
    const std::string technique = GetParam();
    const std::string dir = test::freshTestDir("apitrace");
    const std::string trace = dir + "/run.trace", shot = dir + "/shot.png";
    const std::string size = std::to_string(kSize) + "x" + std::to_string(kSize);
    // Two frames after one warm-up, a small target and fewer instances: the trace stays small and
    // quick, the frame still has casters, receivers and shadows.
    auto traced = runCommand("apitrace trace -o " + trace + " " + std::string(SB_BENCH_BINARY) + " -t " +
                             technique + " --instances 20 --frames 2 --warmup 1 --size " + size +
                             " --no-timer-check -q --screenshot " + shot);
    ASSERT_EQ(traced.exitCode, 0) << traced.output;
    ASSERT_TRUE(std::filesystem::exists(trace)) << traced.output;

    auto dump = runCommand("apitrace dump --color=never " + trace);
    ASSERT_EQ(dump.exitCode, 0) << dump.output.substr(0, 2000);
    // The context creation must be in the trace, else nothing can be replayed.
    EXPECT_NE(dump.output.find("eglCreateContext"), std::string::npos);
    const long readback = lastColorReadback(dump.output);
    ASSERT_GE(readback, 0) << "no colour read-back in the trace";

    const std::string prefix = dir + "/replay-";
    auto replay = runCommand("cd " + dir + " && WAFFLE_PLATFORM=surfaceless_egl eglretrace --headless -S " +
                             std::to_string(readback) + " -s " + prefix + " " + trace);
    ASSERT_EQ(replay.exitCode, 0) << replay.output;
    char name[32];
    std::snprintf(name, sizeof name, "%010ld.png", readback);
    const Rgb8 replayed = readRgb(prefix + name), screenshot = readRgb(shot);
    ASSERT_EQ(screenshot.width, kSize) << "cannot read " << shot;
    ASSERT_EQ(replayed.width, kSize) << "cannot read " << prefix + name << "\n" << replay.output;
    ASSERT_EQ(replayed.height, screenshot.height);
    // A frame of one colour would make the comparison weak (an empty replay of a blank frame): the
    // screenshot must show something, at least two distinct pixel colours.
    std::set<std::array<unsigned char, 3>> colours;
    for (size_t p = 0; p + 2 < screenshot.pixels.size(); p += 3)
        colours.insert({screenshot.pixels[p], screenshot.pixels[p + 1], screenshot.pixels[p + 2]});
    EXPECT_GE(colours.size(), 2u) << "the screenshot is a single colour";
    size_t differing = 0;
    for (size_t i = 0; i < screenshot.pixels.size(); ++i)
        differing += replayed.pixels[i] != screenshot.pixels[i];
    EXPECT_EQ(differing, 0u) << "of " << screenshot.pixels.size() << " channel values";
}

// The LD_PRELOAD rewrite of the hand-off, on the value `apitrace trace` really sets (ld.so's $LIB token
// kept as text) and on values it must leave alone.
TEST(ApitraceHandoff, RewritesOnlyTheGlxTracerEntry) {
    EXPECT_EQ(ApitraceHandoff::eglPreload("/usr/bin/../$LIB/apitrace/wrappers/glxtrace.so"),
              "/usr/bin/../$LIB/apitrace/wrappers/egltrace.so");
    EXPECT_EQ(ApitraceHandoff::eglPreload("/opt/a.so /w/glxtrace.so:/opt/b.so"),
              "/opt/a.so:/w/egltrace.so:/opt/b.so");
    EXPECT_EQ(ApitraceHandoff::eglPreload("/w/egltrace.so"), "");
    EXPECT_EQ(ApitraceHandoff::eglPreload("/w/myglxtrace.so"), "");
    EXPECT_EQ(ApitraceHandoff::eglPreload(""), "");
}

INSTANTIATE_TEST_SUITE_P(EveryTechnique, Apitrace, ::testing::ValuesIn(TechniqueRegistry::namesOn(Api::GL)),
                         [](const auto& param) { return param.param; });

} // namespace
