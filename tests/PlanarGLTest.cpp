// `planar` against ray casts. A ball of radius 0.5 (tessellation 32) over receiver planes: a floor
// pixel is in shadow exactly when the ray from its world position (unprojected from the depth buffer)
// towards the light meets the ball. The flattened polygon is the tessellated sphere's shadow, inside the
// true one by at most R (1 - cos(pi / 64)) = 6e-4 units; pixels are 0.04 units wide; so pixels whose ray
// passes within kBand = 0.06 of the ball's surface are left out and every other pixel must agree: no
// tolerance on the count (a wrong matrix, a missing guard or a lost stencil moves hundreds of pixels).
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "RenderedFrame.h"
#include "TestSupport.h"
#include "bench/lib/harness/Harness.h"
#include "registry/TechniqueRegistry.h"
#include "scenes/Math.h"
#include "techniques/planar/PlanarGL.h"

using namespace sb;

namespace {

constexpr int kSize = 192;
constexpr double kRadius = 0.5, kBand = 0.06;

struct Ball {
    glm::dvec3 centre;
};

/// A floor [-3, 3]^2 at y = 0 (and optionally a wall at x = -2.5 facing +x), balls, lights (JSON), one
/// camera "view".
std::string
writeScene(const std::string& name, const std::vector<Ball>& balls, const std::string& lights,
           bool wall = false, float floorSize = 6, bool floorCasts = false,
           const std::string& camera = R"({"name": "view", "eye": [0, 8, 0.001], "target": [0, 0, 0],
                   "up": [0, 0, -1], "fov": 50, "near": 0.5, "far": 50})") {
    std::string instances =
        R"({"mesh": "floor", "position": [0, 0, 0], "color": [0.5, 0.5, 0.5], "casts_shadow": )" +
        std::string(floorCasts ? "true" : "false") + "}";
    if (wall)
        instances +=
            R"(, {"mesh": "floor", "position": [-2.5, 3, 0], "rotation": [0, 0, -90], "casts_shadow": false,
                       "color": [0.5, 0.5, 0.5]})";
    for (const Ball& b : balls)
        instances += R"(, {"mesh": "ball", "color": [0.9, 0.2, 0.1], "position": [)" +
                     std::to_string(b.centre.x) + ", " + std::to_string(b.centre.y) + ", " +
                     std::to_string(b.centre.z) + "]}";
    const std::string path = test::freshTestDir("planar_" + name) + "/scene.json";
    test::writeFile(path, R"({"name": ")" + name + R"(",
  "meshes": [{"name": "ball", "generator": "sphere", "radius": 0.5, "tessellation": 32},
             {"name": "floor", "generator": "plane", "size": )" +
                              std::to_string(floorSize) + R"(, "tessellation": 1}],
  "instances": [)" + instances +
                              R"(],
  "lights": )" + lights + R"(, "ambient": [0.2, 0.2, 0.2],
  "cameras": [)" + camera + "]}");
    return path;
}

using Frame = test::RenderedFrame;

Frame render(const std::string& scene, const std::string& spec) {
    return test::renderSpec(scene, "view", kSize, spec);
}

/// A light for the ray cast: a point light at `pos` (w = 1) or a directional one travelling along
/// `pos` (w = 0).
struct RayLight {
    glm::dvec3 pos;
    bool point;
};

/// Distance from the ball's centre to the segment (point light) or ray (directional) from p to the light.
double rayDistance(const glm::dvec3& p, const RayLight& l, const glm::dvec3& c) {
    glm::dvec3 dir = l.point ? l.pos - p : -l.pos;
    const double len = l.point ? glm::length(dir) : 1e30;
    dir = glm::normalize(dir);
    const double s = std::clamp(glm::dot(c - p, dir), 0.0, len);
    return glm::length(p + s * dir - c);
}

enum class Verdict { Lit, Shadowed, Band };
Verdict rayCast(const glm::dvec3& p, const RayLight& l, const std::vector<Ball>& balls) {
    Verdict v = Verdict::Lit;
    for (const Ball& b : balls) {
        const double d = rayDistance(p, l, b.centre);
        if (d < kRadius - kBand) return Verdict::Shadowed;
        if (d < kRadius + kBand) v = Verdict::Band;
    }
    return v;
}

// Unprojected depth is good to ~1e-5 here (24 bits over 8 units with near 0.5); 1e-4 keeps the ball's
// surface where it meets the floor (y = 5e-4 one pixel away) out of the floor's pixels.
bool onFloor(const glm::vec4& w, float half = 3.0f) {
    return w.w != 0.0f && std::abs(w.y) < 1e-4f && std::abs(w.x) <= half && std::abs(w.z) <= half;
}
bool onWall(const glm::vec4& w) {
    return w.w != 0.0f && std::abs(w.x + 2.5f) < 1e-4f;
}

struct Tally {
    int mismatches = 0, shadowed = 0, judged = 0, nonFinite = 0;
};

/// Visibility (channel `light`) against the ray cast over the pixels `where` selects.
template <class Where>
Tally judge(const Frame& f, const RayLight& l, const std::vector<Ball>& balls, Where where, int light = 0) {
    Tally t;
    for (size_t i = 0; i < f.world.size(); ++i) {
        const float v = f.visibility[i * 4 + size_t(light)];
        if (!std::isfinite(v)) ++t.nonFinite;
        if (!where(f.world[i])) continue;
        const Verdict want = rayCast(glm::dvec3(f.world[i]), l, balls);
        if (want == Verdict::Band) continue;
        ++t.judged;
        const bool shadowed = v < 0.5f;
        t.shadowed += shadowed;
        t.mismatches += shadowed != (want == Verdict::Shadowed);
        if (shadowed != (want == Verdict::Shadowed) && std::getenv("SB_DEBUG_PLANAR"))
            std::cerr << "mismatch at " << f.world[i].x << " " << f.world[i].y << " " << f.world[i].z << " v "
                      << v << "\n";
    }
    return t;
}

const RayLight kSun{glm::normalize(glm::dvec3(0.4, -1.0, 0.1)), false};
const char* kSunJson = R"([{"type": "directional", "direction": [0.4, -1, 0.1]}])";

} // namespace

TEST(PlanarGLTest, DirectionalShadowMatchesTheRayCast) {
    const std::vector<Ball> balls = {{{0.0, 1.2, 0.0}}};
    const std::string scene = writeScene("sun", balls, kSunJson);
    for (const char* spec : {"planar", "planar:occluder=proxy", "planar:stencil=false"}) {
        SCOPED_TRACE(spec);
        const Frame f = render(scene, spec);
        const Tally t = judge(f, kSun, balls, [](const glm::vec4& w) { return onFloor(w); });
        EXPECT_EQ(t.mismatches, 0);
        EXPECT_GT(t.shadowed, 150); // ~0.85 units^2 (~550 px) less what the ball hides and the band
        EXPECT_EQ(t.nonFinite, 0);
        EXPECT_EQ(test::counter(f.counters, "receiver_planes"), 1.0);
        EXPECT_EQ(test::counter(f.counters, "flattenings"), 1.0);
        // No self-shadowing: the ball's own pixels, its dark side included, are lit.
        for (size_t i = 0; i < f.world.size(); ++i)
            if (f.world[i].w != 0.0f && f.world[i].y > 0.6f) {
                ASSERT_EQ(f.visibility[i * 4], 1.0f);
            }
    }
    // Colour: a shadowed floor pixel is the ambient term only (darkness 1 removes the light exactly), a
    // lit one ambient + n.l; albedo 0.5, ambient 0.2, 8-bit rounding +-1, llvmpipe's blending +-1 more.
    const Frame f = render(scene, "planar");
    const double ndotl = glm::normalize(glm::dvec3(0.4, 1.0, -0.1)).y;
    int checkedShadow = 0, checkedLit = 0;
    for (size_t i = 0; i < f.world.size(); ++i) {
        if (!onFloor(f.world[i])) continue;
        const Verdict want = rayCast(glm::dvec3(f.world[i]), kSun, balls);
        if (want == Verdict::Band) continue;
        const double expected = 255.0 * 0.5 * (0.2 + (want == Verdict::Lit ? ndotl : 0.0));
        EXPECT_NEAR(double(f.colour[i * 4]), expected, 2.0);
        (want == Verdict::Lit ? checkedLit : checkedShadow) += 1;
    }
    EXPECT_GT(checkedShadow, 150);
    EXPECT_GT(checkedLit, 10000);
}

TEST(PlanarGLTest, PointLightShadowsFloorAndWall) {
    // A point light at (2, 5, 0) and the ball at (-1, 1.5, 0): the line through the ball's centre meets
    // the floor at x = -2.29, next to the wall at x = -2.5, so the shadow falls on both. Each receiver
    // plane gets its own flattening.
    const std::vector<Ball> balls = {{{-1.0, 1.5, 0.0}}};
    const RayLight light{{2.0, 5.0, 0.0}, true};
    const std::string scene = writeScene(
        "wall", balls, R"([{"type": "point", "position": [2, 5, 0]}])", true, 6, false,
        R"({"name": "view", "eye": [5, 6, 7], "target": [-1.5, 1.5, 0], "fov": 55, "near": 0.5, "far": 50})");
    const Frame f = render(scene, "planar");
    EXPECT_EQ(test::counter(f.counters, "receiver_planes"), 2.0);
    EXPECT_EQ(test::counter(f.counters, "flattenings"), 2.0);
    const Tally floor = judge(f, light, balls, [](const glm::vec4& w) { return onFloor(w); });
    const Tally wall = judge(f, light, balls, onWall);
    EXPECT_EQ(floor.mismatches, 0);
    EXPECT_EQ(wall.mismatches, 0);
    EXPECT_GT(floor.shadowed, 100);
    EXPECT_GT(wall.shadowed, 50);
}

TEST(PlanarGLTest, StencilDarkensOncePerPixelAndOnlyOnTheReceiver) {
    // Two balls whose shadows overlap (centred at x = -0.1 and 0.36), on a 1.6 x 1.6 floor the second
    // runs off (to x = 0.9), seen from the shadows' side. darkness = 0.5: with the stencil every
    // shadowed floor pixel is exactly 0.5 (darkened once) and nothing beyond the floor changes; without
    // it the overlap darkens twice (0.25) and the shadow lands on the background.
    const std::vector<Ball> balls = {{{-0.5, 1.0, 0.0}}, {{-0.2, 1.4, 0.0}}};
    const std::string scene =
        writeScene("overlap", balls, kSunJson, false, 1.6f, false,
                   R"({"name": "view", "eye": [4, 5, 0.5], "target": [0, 0, 0], "fov": 40,
                   "near": 0.5, "far": 50})");
    const Frame on = render(scene, "planar:darkness=0.5");
    int half = 0;
    for (size_t i = 0; i < on.world.size(); ++i) {
        const float v = on.visibility[i * 4];
        if (on.world[i].w == 0.0f) {
            ASSERT_EQ(v, 1.0f) << "a shadow off the receiver";
        }
        if (!onFloor(on.world[i], 0.8f)) continue;
        ASSERT_TRUE(std::abs(v - 1.0f) < 1e-3f || std::abs(v - 0.5f) < 1e-3f) << v;
        half += std::abs(v - 0.5f) < 1e-3f;
    }
    EXPECT_GT(half, 200);
    const Frame off = render(scene, "planar:darkness=0.5:stencil=false");
    int quarter = 0, offReceiver = 0;
    for (size_t i = 0; i < off.world.size(); ++i) {
        const float v = off.visibility[i * 4];
        if (onFloor(off.world[i], 0.8f)) quarter += std::abs(v - 0.25f) < 1e-3f;
        if (off.world[i].w == 0.0f) offReceiver += v < 0.99f;
    }
    EXPECT_GT(quarter, 100) << "double blending must show without the stencil";
    EXPECT_GT(offReceiver, 30) << "the shadow must run off the receiver without the stencil";
}

TEST(PlanarGLTest, GuardsStopWrongShadowsAndAntiShadows) {
    struct Case {
        const char* name;
        std::vector<Ball> balls;
        RayLight light;
        std::string json;
        int minWrongUnguarded; ///< the artefact the guard removes must show without it
    };
    const Case cases[] = {
        // Occluder partly behind the receiver: the ball sinks 0.7 into the floor under a low sun; its
        // lower part would flatten onto the floor on the light's side (a wrong shadow out to x = -1.4).
        {"behind_receiver",
         {{{0.0, -0.2, 0.0}}},
         {glm::normalize(glm::dvec3(1.0, -0.5, 0.0)), false},
         R"([{"type": "directional", "direction": [1, -0.5, 0]}])",
         100},
        // The light between occluder and receiver: a point light at height 2 under a ball spanning
        // heights 2.1..3.1. Every ray from the floor to the light stays below the ball; flattened
        // through the light, the ball lands on the far side (an anti-shadow over x = -0.9 .. -3.3).
        {"light_between",
         {{{0.5, 2.6, 0.0}}},
         {{0.0, 2.0, 0.0}, true},
         R"([{"type": "point", "position": [0, 2, 0]}])",
         100},
        // The light below the ground plane: it lights the floor's back; nothing may land on the front
        // (unguarded, the ball's image lands around x = 1.1, clear of the ball seen from above).
        {"light_below",
         {{{0.0, 1.2, 0.0}}},
         {{3.0, -2.0, 0.0}, true},
         R"([{"type": "point", "position": [3, -2, 0]}])",
         100},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const std::string scene = writeScene(c.name, c.balls, c.json);
        const bool below = c.light.point && c.light.pos.y < 0.0;
        const Frame f = render(scene, "planar");
        const Tally t = judge(f, c.light, c.balls, [](const glm::vec4& w) { return onFloor(w); });
        // Seen from below, the ray cast says the ball shadows nothing of the floor's front.
        EXPECT_EQ(below ? t.shadowed : t.mismatches, 0);
        EXPECT_EQ(t.nonFinite, 0);
        EXPECT_EQ(test::counter(f.counters, "flattenings"), below ? 0.0 : 1.0);
        const Frame raw = render(scene, "planar:guards=false");
        const Tally u = judge(raw, c.light, c.balls, [](const glm::vec4& w) { return onFloor(w); });
        EXPECT_GE(below ? u.shadowed : u.mismatches, c.minWrongUnguarded);
    }
}

TEST(PlanarGLTest, LightInTheReceiverPlaneCastsNothingAndStaysFinite) {
    // A directional light exactly along the floor: P.L = 0, the matrix collapses every point onto the
    // light's point at infinity. Guarded: no flattening; unguarded: whatever is drawn stays finite.
    const std::vector<Ball> balls = {{{0.0, 1.2, 0.0}}};
    const std::string scene =
        writeScene("in_plane", balls, R"([{"type": "directional", "direction": [1, 0, 0]}])");
    for (const char* spec : {"planar", "planar:guards=false"}) {
        SCOPED_TRACE(spec);
        const Frame f = render(scene, spec);
        for (float v : f.visibility) ASSERT_TRUE(std::isfinite(v) && v >= 0.0f && v <= 1.0f) << v;
    }
    EXPECT_EQ(test::counter(render(scene, "planar").counters, "flattenings"), 0.0);
}

TEST(PlanarGLTest, WithoutReceiverPlanesNothingIsShadowed) {
    // The floor casts shadows, so it is not a receiver plane (it would be flattened onto itself).
    const std::vector<Ball> balls = {{{0.0, 1.2, 0.0}}};
    const Frame f = render(writeScene("no_plane", balls, kSunJson, false, 6, true), "planar");
    EXPECT_EQ(test::counter(f.counters, "receiver_planes"), 0.0);
    for (size_t i = 0; i < f.world.size(); ++i) ASSERT_EQ(f.visibility[i * 4], 1.0f);
}
