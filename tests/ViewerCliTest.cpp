// `bench --window` on a real X display (scripts/test.sh runs ctest under xvfb-run): the viewer is started
// as a user would start it, its window found with xdotool, screenshots taken with xwd and read here
// (tests/ViewerCliTest.cpp parses the XWD format itself: no image tool is needed), and keys sent as a
// user's taps. Checked against answers the viewer does not compute:
//   - the overlay's text, pixel by pixel, against the glyphs of the bitmap font table
//     (bench/lib/font/BitmapFont.h) at the position the overlay's header documents
//     (bench/lib/viewer/Overlay.h);
//   - the light count against the scene file (scenes/data/sphere_plane.json), the timer line against
//     what --no-timer-check means (verdict "unchecked");
//   - one Tab tap, sent once and released at once (a tap between two frames, which polling lost),
//     switches exactly once: the log line and the overlay's name both change;
//   - V turns the window into the documented false-colour ramp (bench/lib/viewer/VisibilityView.h): every
//     pixel below the overlay lies on the ramp, with both lit and shadowed pixels present.
#include <array>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <optional>
#include <string>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "TestSupport.h"
#include "bench/lib/font/BitmapFont.h"
#include "bench/lib/viewer/Overlay.h"
#include "bench/lib/viewer/RollingMedian.h"
#include "registry/TechniqueRegistry.h"

using namespace sb;
using test::runCommand;

namespace {

using Clock = std::chrono::steady_clock;

// Small, so that llvmpipe draws a frame in milliseconds on a loaded 2-core machine, and below 700
// pixels on both sides, so that the overlay draws one window pixel per font pixel (Overlay::scaleFor).
constexpr int kWidth = 480, kHeight = 360;
constexpr int kScale = 1;
// Generous: bench starts (scene, GLFW, shader compiles) in about a second when idle, and the suite runs
// other tests beside this one.
constexpr auto kWait = std::chrono::seconds(20);

struct Rgb {
    int r = 0, g = 0, b = 0;
};

/// A screenshot, rows top-down as X stores them.
struct Image {
    int width = 0, height = 0;
    std::vector<Rgb> pixels;
    const Rgb& at(int x, int y) const { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
};

uint32_t bigEndian32(const std::string& d, size_t at) {
    return uint32_t(uint8_t(d[at])) << 24 | uint32_t(uint8_t(d[at + 1])) << 16 |
           uint32_t(uint8_t(d[at + 2])) << 8 | uint32_t(uint8_t(d[at + 3]));
}

/// Reads an XWD file (X11/XWDFile.h's format, version 7) of a TrueColor or DirectColor ZPixmap at 24 or
/// 32 bits per pixel, which is what xwd writes for a window of a 24-bit Xvfb screen. The header is 25
/// big-endian 32-bit fields followed by the window name (header_size covers both), then ncolors
/// 12-byte colour entries, then the pixels in the server's byte order with bytes_per_line per row.
std::optional<Image> readXwd(const std::string& path, std::string& error) {
    const std::string d = test::readFile(path);
    if (d.size() < 100) {
        error = "shorter than an XWD header: " + std::to_string(d.size()) + " bytes";
        return std::nullopt;
    }
    auto field = [&](int i) { return bigEndian32(d, size_t(i) * 4); };
    const uint32_t headerSize = field(0), version = field(1), format = field(2), width = field(4),
                   height = field(5), byteOrder = field(7), bitsPerPixel = field(11),
                   bytesPerLine = field(12), visualClass = field(13), ncolors = field(19);
    const uint32_t masks[3] = {field(14), field(15), field(16)};
    if (version != 7 || format != 2 || (bitsPerPixel != 24 && bitsPerPixel != 32) ||
        (visualClass != 4 && visualClass != 5)) {
        error = "unsupported XWD: version " + std::to_string(version) + ", format " + std::to_string(format) +
                ", " + std::to_string(bitsPerPixel) + " bpp, visual class " + std::to_string(visualClass);
        return std::nullopt;
    }
    const size_t data = size_t(headerSize) + size_t(ncolors) * 12;
    if (d.size() < data + size_t(bytesPerLine) * height) {
        error = "truncated XWD (" + std::to_string(d.size()) + " bytes)";
        return std::nullopt;
    }
    Image img;
    img.width = int(width);
    img.height = int(height);
    img.pixels.resize(size_t(width) * height);
    const size_t bytes = bitsPerPixel / 8;
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            const size_t at = data + size_t(y) * bytesPerLine + size_t(x) * bytes;
            uint32_t pixel = 0;
            for (size_t k = 0; k < bytes; ++k) {
                const uint32_t byte = uint8_t(d[at + k]);
                pixel |= byteOrder == 0 ? byte << (8 * k) : byte << (8 * (bytes - 1 - k)); // 0: LSBFirst
            }
            int channel[3];
            for (int c = 0; c < 3; ++c) {
                uint32_t m = masks[c], v = pixel & m;
                while (m && !(m & 1u)) {
                    m >>= 1;
                    v >>= 1;
                }
                channel[c] = m ? int((v * 255u + m / 2) / m) : 0; // scaled to 0..255 whatever the mask width
            }
            img.pixels[size_t(y) * width + x] = {channel[0], channel[1], channel[2]};
        }
    return img;
}

/// The bench process of one test: started with its stdout and stderr in a file, killed (and reaped) when
/// the object goes; PR_SET_PDEATHSIG kills it too if this test process dies first.
class BenchProcess {
public:
    BenchProcess(const std::vector<std::string>& args, const std::string& logPath) : mLog(logPath) {
        mPid = fork();
        if (mPid == 0) {
            prctl(PR_SET_PDEATHSIG, SIGKILL);
            const int fd = open(logPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            dup2(fd, 1);
            dup2(fd, 2);
            std::vector<char*> argv;
            for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
            argv.push_back(nullptr);
            execv(argv[0], argv.data());
            _exit(127);
        }
    }
    ~BenchProcess() {
        if (mPid <= 0) return;
        kill(mPid, SIGKILL);
        waitpid(mPid, nullptr, 0);
    }
    BenchProcess(const BenchProcess&) = delete;
    BenchProcess& operator=(const BenchProcess&) = delete;

    pid_t pid() const { return mPid; }
    std::string output() const { return test::readFile(mLog); }
    bool running() const { return mPid > 0 && waitpid(mPid, nullptr, WNOHANG) == 0; }
    /// Waits until the output holds `text` (true) or the process ended or kWait passed (false).
    bool waitFor(const std::string& text) const {
        const auto end = Clock::now() + kWait;
        while (Clock::now() < end) {
            if (output().find(text) != std::string::npos) return true;
            if (!running()) return output().find(text) != std::string::npos;
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
        return false;
    }

private:
    pid_t mPid = -1;
    std::string mLog;
};

/// The lines of `output` that start with `prefix`.
std::vector<std::string> linesStartingWith(const std::string& output, const std::string& prefix) {
    std::vector<std::string> lines;
    size_t pos = 0;
    while (pos < output.size()) {
        size_t end = output.find('\n', pos);
        if (end == std::string::npos) end = output.size();
        if (output.compare(pos, prefix.size(), prefix) == 0) lines.push_back(output.substr(pos, end - pos));
        pos = end + 1;
    }
    return lines;
}

std::optional<Image> screenshot(const std::string& window, const std::string& path, std::string& error) {
    const auto r = runCommand("xwd -silent -id " + window + " -out " + path);
    if (r.exitCode != 0) {
        error = "xwd failed: " + r.output;
        return std::nullopt;
    }
    return readXwd(path, error);
}

// Tolerances of the overlay's pixels (bench/lib/viewer/Overlay.h). Ink is opaque white drawn without
// blending: exact 255 on an 8-bit-per-channel window; 5 below is left for a server that stores fewer
// bits. Blank pixels inside the box are the image under black at kBoxOpacity: at most
// 255 * (1 - 0.6) = 102, plus 8 for rounding and the same fewer-bits allowance.
constexpr int kInkMin = 250;
const int kDimMax = int(255.0f * (1.0f - Overlay::kBoxOpacity) + 0.5f) + 8;

/// Compares text line `row` of the overlay with `text` drawn in the font: every font pixel of every
/// character cell (including the blank column after each glyph but the last). Returns "" when all
/// match, else the first mismatches.
std::string checkOverlayLine(const Image& img, int row, const std::string& text) {
    const int inset = Overlay::kMargin + Overlay::kPadding * kScale;
    const int top = inset + row * Overlay::kLineHeight * kScale;
    std::string errors;
    int count = 0;
    for (size_t i = 0; i < text.size(); ++i)
        for (int gy = 0; gy < BitmapFont::kGlyphHeight; ++gy)
            for (int gx = 0; gx < (i + 1 < text.size() ? BitmapFont::kCellWidth : BitmapFont::kGlyphWidth);
                 ++gx) {
                const bool ink = BitmapFont::pixel(text[i], gx, gy);
                for (int sy = 0; sy < kScale; ++sy)
                    for (int sx = 0; sx < kScale; ++sx) {
                        const int x = inset + (int(i) * BitmapFont::kCellWidth + gx) * kScale + sx;
                        const int y = top + gy * kScale + sy;
                        const Rgb& p = img.at(x, y);
                        const int lo = std::min({p.r, p.g, p.b}), hi = std::max({p.r, p.g, p.b});
                        if (ink ? lo >= kInkMin : hi <= kDimMax) continue;
                        if (++count <= 5)
                            errors += "  '" + std::string(1, text[i]) + "' at (" + std::to_string(x) + ", " +
                                      std::to_string(y) + "): (" + std::to_string(p.r) + ", " +
                                      std::to_string(p.g) + ", " + std::to_string(p.b) + "), expected " +
                                      (ink ? "ink (white)" : "dimmed box") + "\n";
                    }
            }
    if (count > 5) errors += "  ... " + std::to_string(count - 5) + " more\n";
    return errors.empty() ? ""
                          : "overlay line " + std::to_string(row) + " is not \"" + text + "\":\n" + errors;
}

/// The false-colour ramp as bench/lib/viewer/VisibilityView.h documents it, in 0..255: dark blue at 0 through
/// purple and orange to pale yellow at 1, linear between the four stops.
const std::array<std::array<double, 3>, 4> kRampStops = {{{0.05 * 255, 0.03 * 255, 0.30 * 255},
                                                          {0.55 * 255, 0.10 * 255, 0.55 * 255},
                                                          {0.95 * 255, 0.50 * 255, 0.15 * 255},
                                                          {1.00 * 255, 0.97 * 255, 0.75 * 255}}};

/// The visibility whose ramp colour is nearest to `p`, and how far (largest channel difference).
std::pair<double, double> nearestOnRamp(const Rgb& p) {
    double bestV = 0.0, bestD = 1e9;
    for (int i = 0; i <= 300; ++i) {
        const double v = i / 300.0, t = v * 3.0;
        const int s = std::min(int(t), 2);
        double d = 0.0;
        const int c[3] = {p.r, p.g, p.b};
        for (int k = 0; k < 3; ++k)
            d = std::max(
                d,
                std::abs(kRampStops[size_t(s)][size_t(k)] +
                         (kRampStops[size_t(s) + 1][size_t(k)] - kRampStops[size_t(s)][size_t(k)]) * (t - s) -
                         c[k]));
        if (d < bestD) {
            bestD = d;
            bestV = v;
        }
    }
    return {bestV, bestD};
}

int sceneLightCount(const std::string& scene) {
    const auto json =
        nlohmann::json::parse(test::readFile(std::string(SB_SOURCE_DIR) + "/scenes/data/" + scene + ".json"));
    return int(json.at("lights").size());
}

// The overlay's frame time: the median of the last N frames only, so one slow frame moves nothing.
TEST(ViewerCliTest, FrameTimeIsTheMedianOfTheLastFrames) {
    RollingMedian m(3);
    EXPECT_EQ(m.median(), 0.0);
    for (double v : {1.0, 2.0, 100.0}) m.add(v);
    EXPECT_EQ(m.median(), 2.0); // one slow frame among three
    m.add(3.0);                 // 1 drops out: {2, 100, 3}
    EXPECT_EQ(m.median(), 3.0);
    m.add(4.0);
    m.add(5.0); // {4, 5, 3}: the slow frame is gone
    EXPECT_EQ(m.median(), 4.0);
    EXPECT_EQ(m.count(), 3u);
    RollingMedian even(4);
    for (double v : {10.0, 1.0, 3.0, 2.0}) even.add(v);
    EXPECT_EQ(even.median(), 2.5); // the mean of the two middle values
}

// Long property strings wrap after a ':' or ' ' (Overlay.h); a word longer than the line is cut.
TEST(ViewerCliTest, OverlayLinesWrapAfterSeparators) {
    EXPECT_EQ(Overlay::wrap("properties: a=1:b=2:c=3", 12),
              (std::vector<std::string>{"properties: ", "a=1:b=2:c=3"}));
    EXPECT_EQ(Overlay::wrap("a=1:b=2:c=3", 8), (std::vector<std::string>{"a=1:b=2:", "c=3"}));
    EXPECT_EQ(Overlay::wrap("abcdefghij", 4), (std::vector<std::string>{"abcd", "efgh", "ij"}));
    EXPECT_EQ(Overlay::wrap("", 4), (std::vector<std::string>{""}));
}

TEST(ViewerCliTest, OverlayShowsTheTechniqueAndATapSwitchesIt) {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no DISPLAY (scripts/test.sh runs the suite under xvfb-run)";
    if (runCommand("command -v xdotool && command -v xwd").exitCode != 0)
        GTEST_SKIP() << "needs xdotool and xwd: apt-get install xdotool x11-apps";
    const std::string dir = test::freshTestDir("viewer");
    const std::string scene = "sphere_plane";
    // --no-timer-check: no calibration (a second less), and a verdict the test knows: "unchecked".
    BenchProcess bench({SB_BENCH_BINARY, "--window", "-t", "none", "-t", "shadowmap", "--scene", scene,
                        "--size", std::to_string(kWidth) + "x" + std::to_string(kHeight), "--no-timer-check"},
                       dir + "/bench.log");
    ASSERT_GT(bench.pid(), 0) << "fork failed";
    ASSERT_TRUE(bench.waitFor("viewer: technique none\n")) << "the viewer never showed its first frame:\n"
                                                           << bench.output();

    // The window of this bench process (GLFW sets _NET_WM_PID), titled "shadowbench: ...".
    const auto search = runCommand("timeout 15 xdotool search --sync --onlyvisible --pid " +
                                   std::to_string(bench.pid()) + " --name '^shadowbench'");
    ASSERT_EQ(search.exitCode, 0) << "no window found:\n" << search.output << "\nbench:\n" << bench.output();
    const std::string window = search.output.substr(0, search.output.find('\n'));

    std::string error;
    auto first = screenshot(window, dir + "/none.xwd", error);
    ASSERT_TRUE(first) << error;
    ASSERT_EQ(first->width, kWidth);
    ASSERT_EQ(first->height, kHeight);
    // Lines 0, 1, 3, 4, 5 in bench/lib/viewer/Viewer.cpp's order: name, properties, times (line 2, which
    // vary and are not checked), timer, lights, view. "none" has no properties, so nothing wraps.
    EXPECT_EQ(checkOverlayLine(*first, 0, "none"), "");
    EXPECT_EQ(checkOverlayLine(*first, 1, "properties: none"), "");
    EXPECT_EQ(checkOverlayLine(*first, 3, "GPU timer: unchecked"), "");
    EXPECT_EQ(checkOverlayLine(*first, 4, "lights: " + std::to_string(sceneLightCount(scene))), "");
    EXPECT_EQ(checkOverlayLine(*first, 5, "view: colour"), "");

    // One tap: press and release sent at once, typically within one frame; the viewer must see it.
    const auto tab = runCommand("xdotool key --window " + window + " Tab");
    ASSERT_EQ(tab.exitCode, 0) << tab.output;
    ASSERT_TRUE(bench.waitFor("viewer: technique shadowmap\n")) << "Tab did not switch:\n" << bench.output();
    auto second = screenshot(window, dir + "/shadowmap.xwd", error);
    ASSERT_TRUE(second) << error;
    EXPECT_EQ(checkOverlayLine(*second, 0, "shadowmap"), "");
    // The first property as the technique states it (the line wraps further on, after a ':').
    const std::string properties = TechniqueRegistry::create("shadowmap")->properties().toString();
    EXPECT_EQ(checkOverlayLine(*second, 1, "properties: " + properties.substr(0, properties.find(':') + 1)),
              "");

    // V: the visibility of light 1 through the ramp, with its legend.
    const auto v = runCommand("xdotool key --window " + window + " v");
    ASSERT_EQ(v.exitCode, 0) << v.output;
    ASSERT_TRUE(bench.waitFor("viewer: view visibility of light 1\n")) << "V did not switch:\n"
                                                                       << bench.output();
    auto third = screenshot(window, dir + "/visibility.xwd", error);
    ASSERT_TRUE(third) << error;
    // Below the overlay box the window is the ramp alone. The box has 11 rows at this width (6 lines, 2
    // more for the wrapped properties, 3 for the legend); 16 are allowed, so that a property added to
    // shadowmap does not move the box over the checked region (which still holds the sphere's shadow,
    // about 190..210 pixels down). 3 of 255 per channel: the ramp is computed in float and stored in
    // 8 bits (half a step), and the texel's half-float visibility moves the point along the ramp, not
    // off it.
    const int below = Overlay::kMargin + 2 * Overlay::kPadding + 16 * Overlay::kLineHeight;
    int off = 0, lit = 0, shadowed = 0;
    std::string offText;
    for (int y = below; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const auto [vis, distance] = nearestOnRamp(third->at(x, y));
            if (distance > 3.0) {
                if (++off <= 3) {
                    const Rgb& p = third->at(x, y);
                    offText += " (" + std::to_string(x) + ", " + std::to_string(y) +
                               ")=" + std::to_string(p.r) + "," + std::to_string(p.g) + "," +
                               std::to_string(p.b);
                }
                continue;
            }
            lit += vis > 0.99;
            shadowed += vis < 0.01;
        }
    EXPECT_EQ(off, 0) << "pixels off the visibility ramp:" << offText;
    // The sphere lit by its directional light casts a shadow on the plane (shadowmap: hard, so fully
    // shadowed texels); the rest of the plane and the background are lit.
    EXPECT_GT(lit, 0);
    EXPECT_GT(shadowed, 0);

    // Exactly one switch per tap, in order.
    const auto switches = linesStartingWith(bench.output(), "viewer: technique ");
    EXPECT_EQ(switches, (std::vector<std::string>{"viewer: technique none", "viewer: technique shadowmap"}));
    EXPECT_TRUE(bench.running()) << bench.output();
    // The screenshots (about 0.7 MB each) stay behind only when something failed, to be looked at.
    if (!::testing::Test::HasFailure()) std::filesystem::remove_all(dir);
}

} // namespace
