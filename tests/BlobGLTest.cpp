// `blob` rendered against hand-computed ellipses. Boxes with half extent 0.5 whose bottoms are 1 above
// a floor: an overhead sun gives each the circle through its footprint's corners (radius 0.5 sqrt(2))
// under it, a sun along (1, -1, 0) an ellipse centred 1.5 further along x (corners move by their
// height: x = 0.5, 1.5, 1.5, 2.5, variance 0.5; z variance 0.25) with semi-axes 1 (x) and 0.5 sqrt(2) (z).
// Opacity 1 - 1 / (fade 8 * bounding radius sqrt(3)/2) = 0.8557. Every visible floor pixel is judged at
// its unprojected world position: v = 1 - opacity (1 - smoothstep(1 - softness, 1, r)). Tolerance 2e-3:
// the RGBA16F target resolves 4.9e-4 near 1, the unprojected position is good to ~1e-5.
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "RenderedFrame.h"
#include "TestSupport.h"
#include "bench/lib/harness/Harness.h"
#include "registry/TechniqueRegistry.h"
#include "scenes/Math.h"

using namespace sb;

namespace {

constexpr int kSize = 192;
const double kOpacity = 1.0 - 1.0 / (8.0 * std::sqrt(3.0) / 2.0);
const double kR = 0.5 * std::sqrt(2.0);

std::string writeScene(const std::string& name, const std::string& boxes, const std::string& lights,
                       bool floorCasts = false) {
    const std::string path = test::freshTestDir("blob_" + name) + "/scene.json";
    test::writeFile(path, R"({"name": ")" + name + R"(",
  "meshes": [{"name": "box", "generator": "box", "half_extent": [0.5, 0.5, 0.5]},
             {"name": "floor", "generator": "plane", "size": 8, "tessellation": 1}],
  "instances": [{"mesh": "floor", "position": [0, 0, 0], "color": [0.5, 0.5, 0.5], "casts_shadow": )" +
                              std::string(floorCasts ? "true" : "false") + "}, " + boxes + R"(],
  "lights": )" + lights + R"(, "ambient": [0.2, 0.2, 0.2],
  "cameras": [{"name": "view", "eye": [3.5, 7, 0.001], "target": [0.5, 0, 0], "up": [0, 0, -1], "fov": 50,
               "near": 0.5, "far": 50}]})");
    return path;
}

using Frame = test::RenderedFrame;

Frame render(const std::string& scene, const std::string& spec) {
    return test::renderSpec(scene, "view", kSize, spec);
}

double smoothstep(double e0, double e1, double x) {
    const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

/// Visibility of one blob at floor point (x, z): ellipse centre (cx, cz), semi-axes a (x), b (z).
double blob(double x, double z, double cx, double cz, double a, double b, double softness) {
    const double r = std::hypot((x - cx) / a, (z - cz) / b);
    const double profile = softness > 0.0 ? 1.0 - smoothstep(1.0 - softness, 1.0, r) : (r <= 1.0 ? 1.0 : 0.0);
    return 1.0 - kOpacity * profile;
}

/// Largest |v - expected| over visible floor pixels in channel `light`; `darkened` counts v < 0.99.
double worst(const Frame& f, int light, const std::function<double(double, double)>& expected,
             int* darkened) {
    double w = 0.0;
    *darkened = 0;
    for (size_t i = 0; i < f.world.size(); ++i) {
        const glm::vec4 p = f.world[i];
        if (p.w == 0.0f || std::abs(p.y) > 1e-4f) continue;
        const double v = f.visibility[i * 4 + size_t(light)];
        *darkened += v < 0.99;
        if (std::getenv("SB_DEBUG_BLOB") && std::abs(v - expected(p.x, p.z)) > 2e-3)
            std::cerr << p.x << " " << p.z << " got " << v << " want " << expected(p.x, p.z) << "\n";
        w = std::max(w, std::abs(v - expected(p.x, p.z)));
    }
    return w;
}

const char* kBox = R"({"mesh": "box", "position": [0, 1.5, 0], "color": [0.9, 0.2, 0.1]})";

} // namespace

TEST(BlobGLTest, OverheadSunGivesTheSoftCircle) {
    const std::string scene =
        writeScene("overhead", kBox, R"([{"type": "directional", "direction": [0, -1, 0]}])");
    for (double softness : {0.5, 1.0}) {
        const Frame f = render(scene, "blob:softness=" + std::to_string(softness));
        int darkened = 0;
        EXPECT_LT(
            worst(
                f, 0, [&](double x, double z) { return blob(x, z, 0, 0, kR, kR, softness); }, &darkened),
            2e-3);
        EXPECT_GT(darkened, 50); // the part the box does not hide, seen from the side
        EXPECT_EQ(test::counter(f.counters, "blobs"), 1.0);
    }
    // Colour on the floor: albedo 0.5 * (ambient 0.2 + the light's share left, n.l = 1), 8-bit +-2.
    const Frame f = render(scene, "blob");
    for (size_t i = 0; i < f.world.size(); ++i) {
        const glm::vec4 p = f.world[i];
        if (p.w == 0.0f || std::abs(p.y) > 1e-4f) continue;
        const double v = blob(p.x, p.z, 0, 0, kR, kR, 0.5);
        ASSERT_NEAR(double(f.colour[i * 4]), 255.0 * 0.5 * (0.2 + v), 2.0);
    }
}

TEST(BlobGLTest, EachLightGetsItsOwnEllipseInItsChannel) {
    const std::string scene = writeScene(
        "two_lights", kBox,
        R"([{"type": "directional", "direction": [0, -1, 0]}, {"type": "directional", "direction": [1, -1, 0]}])");
    const Frame f = render(scene, "blob");
    EXPECT_EQ(test::counter(f.counters, "blobs"), 2.0);
    int d0 = 0, d1 = 0;
    EXPECT_LT(worst(
                  f, 0, [](double x, double z) { return blob(x, z, 0, 0, kR, kR, 0.5); }, &d0),
              2e-3);
    EXPECT_LT(worst(
                  f, 1, [](double x, double z) { return blob(x, z, 1.5, 0, 1.0, kR, 0.5); }, &d1),
              2e-3);
    EXPECT_GT(d1, 500); // the stretched ellipse lies mostly beside the box
    for (size_t i = 0; i < f.world.size(); ++i) {
        ASSERT_EQ(f.visibility[i * 4 + 2], 1.0f);
        ASSERT_EQ(f.visibility[i * 4 + 3], 1.0f);
    }
}

TEST(BlobGLTest, OverlappingBlobsMultiply) {
    // Two boxes 0.6 apart: their circles (radius 0.71) overlap between x = -0.41 and 0.41 (at z = 0).
    const std::string boxes =
        R"({"mesh": "box", "position": [-0.3, 1.5, 0]}, {"mesh": "box", "position": [0.3, 1.5, 0]})";
    const Frame f =
        render(writeScene("overlap", boxes, R"([{"type": "directional", "direction": [0, -1, 0]}])"),
               "blob:softness=1");
    int darkened = 0;
    EXPECT_LT(
        worst(
            f, 0,
            [](double x, double z) { return blob(x, z, -0.3, 0, kR, kR, 1) * blob(x, z, 0.3, 0, kR, kR, 1); },
            &darkened),
        2e-3);
    EXPECT_GT(darkened, 50);
}

TEST(BlobGLTest, NoGroundNoBlobs) {
    const Frame f = render(
        writeScene("no_ground", kBox, R"([{"type": "directional", "direction": [0, -1, 0]}])", true), "blob");
    EXPECT_EQ(test::counter(f.counters, "blobs"), 0.0);
    for (size_t i = 0; i < f.world.size(); ++i) ASSERT_EQ(f.visibility[i * 4], 1.0f);
}
