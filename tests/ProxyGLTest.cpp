// `proxy` against closed forms. A ball of radius R at height H over a floor (the floor casts nothing):
// the fitted proxy is that sphere (the sphere mesh's vertices lie on it, the sphere is the tightest
// fit), so at a floor point p the distance to the proxy is |p - c| - R, the direction the shadow is
// cast along is (p - c) / |p - c|, and Listings 1.3 and 1.4 give the visibility in closed form:
//   v = 1 - clamp(pow(1 - min(d / offset, 1), falloff) * shadow * clamp(dot(L, n), cutoff, 1), 0, 1).
// Every floor pixel is judged at the world position unprojected from the depth buffer. The closed form
// is Listing 1.4 as printed (modulate=on); the default (modulate=rays) keeps that value only where the
// ray towards the light passes the proxy, which the hard case proxy_grazing_poles (tests/hard/HardCases.h)
// holds against the reference.
// Tolerance 2e-3: the position the test unprojects and the one the rasteriser interpolates agree to
// ~1e-5 units (float matrices, 24-bit depth at 8 units), which moves v by ~1e-5 / offset; the rest is
// headroom for the shader's float arithmetic. A wrong sign of the modulation, a missing exponent or a
// proxy dropped by the grid moves v by far more than that on hundreds of pixels.
#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "RenderedFrame.h"
#include "TestSupport.h"
#include "bench/lib/harness/Harness.h"
#include "scenes/Math.h"
#include "techniques/proxy/ProxyGL.h"

using namespace sb;

namespace {

constexpr int kSize = 192;
constexpr double kRadius = 0.5, kHeight = 1.2;

/// Floor [-3, 3]^2 at y = 0 (receives, casts nothing) and a ball at (0, kHeight, 0); `lights` and
/// `effects` are JSON arrays.
std::string writeScene(const std::string& dir, const std::string& lights, const std::string& effects) {
    const std::string path = dir + "/scene.json";
    test::writeFile(path, R"({"name": "ball_floor",
  "meshes": [{"name": "ball", "generator": "sphere", "radius": 0.5, "tessellation": 24},
             {"name": "floor", "generator": "plane", "size": 6, "tessellation": 1}],
  "instances": [{"mesh": "floor", "position": [0, 0, 0], "casts_shadow": false, "color": [0.5, 0.5, 0.5]},
                {"mesh": "ball", "position": [0, 1.2, 0], "color": [0.9, 0.2, 0.1]}],
  "lights": )" + lights + R"(,
  "effects": )" + effects + R"(,
  "cameras": [{"name": "top", "eye": [0, 8, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fov": 50,
               "near": 0.5, "far": 50}]})");
    return path;
}

using Frame = test::RenderedFrame;

Frame render(const std::string& scene, const std::string& spec) {
    return test::renderSpec(scene, "top", kSize, spec);
}

const char* kOneLight = R"([{"type": "directional", "direction": [0.4, -1, 0.1]}])";

struct Shading {
    double offset = 1.0, shadow = 1.0, falloff = 1.0, cutoff = 0.0;
    bool exponentOnFactor = false, modulate = true;
};

/// The closed form at floor point p for a light travelling along `travel`.
double expected(const glm::dvec3& p, const glm::dvec3& travel, const Shading& s) {
    const glm::dvec3 c(0.0, kHeight, 0.0);
    const double d = std::max(glm::length(p - c) - kRadius, 0.0);
    if (d > s.offset) return 1.0;
    const double base = s.offset > 0.0 ? 1.0 - std::min(d / s.offset, 1.0) : (d <= 0.0 ? 1.0 : 0.0);
    double shadow =
        s.exponentOnFactor ? base * std::pow(s.shadow, s.falloff) : std::pow(base, s.falloff) * s.shadow;
    if (s.modulate)
        shadow *= std::clamp(glm::dot(glm::normalize(travel), glm::normalize(p - c)), s.cutoff, 1.0);
    return 1.0 - std::clamp(shadow, 0.0, 1.0);
}

bool isFloor(const glm::vec4& w) {
    return w.w != 0.0f && std::abs(w.y) < 1e-3f;
}

/// Largest |visibility - closed form| over floor pixels, channel `light`; `shadowed` counts v < 0.99.
double worstError(const Frame& f, int light, const glm::dvec3& travel, const Shading& s, int* shadowed) {
    double worst = 0.0;
    *shadowed = 0;
    for (size_t i = 0; i < f.world.size(); ++i) {
        if (!isFloor(f.world[i])) continue;
        const double v = f.visibility[i * 4 + size_t(light)];
        EXPECT_TRUE(std::isfinite(v));
        *shadowed += v < 0.99;
        worst = std::max(worst, std::abs(v - expected(glm::dvec3(f.world[i]), travel, s)));
    }
    return worst;
}

const glm::dvec3 kTravel(0.4, -1.0, 0.1);

} // namespace

TEST(ProxyGLTest, ModulatedShadowMatchesTheClosedForm) {
    const std::string scene = writeScene(test::freshTestDir("proxy"), kOneLight, "[]");
    Shading s;
    s.offset = 2.0;
    int shadowed = 0;
    const Frame grid = render(scene, "proxy:offset=2:modulate=on");
    EXPECT_LT(worstError(grid, 0, kTravel, s, &shadowed), 2e-3);
    // The halo reaches the floor (d = 0.7 under the ball against offset 2): thousands of pixels.
    EXPECT_GT(shadowed, 1000);
    // The ball's own pixels are skipped by its own proxy (Listing 1.2's self-shadow test): fully lit.
    for (size_t i = 0; i < grid.world.size(); ++i)
        if (grid.world[i].w != 0.0f && grid.world[i].y > 0.5f) {
            EXPECT_EQ(grid.visibility[i * 4], 1.0f);
        }
    // grid=off tests the same proxy in every fragment: the same image, bit for bit.
    const Frame brute = render(scene, "proxy:offset=2:modulate=on:grid=false");
    EXPECT_EQ(grid.visibility, brute.visibility);
    EXPECT_NE(grid.permutation.find("PROXY_GRID"), std::string::npos);
    EXPECT_EQ(brute.permutation.find("PROXY_GRID"), std::string::npos);
}

/// modulate=rays (the default) at floor point p: Listing 1.4's shadow times how much the ball hides the
/// light along the ray towards it, u = -travel. The ray's closest approach to the centre is at
/// t = max(0, (c - p).u), missing the ball by m = |p + t u - c| - R: hidden (1) for m <= 0, else
/// 1 - clamp(m / (tan(penumbra) t)), the shader's miss ratio at that point (for a sphere its nearest).
double expectedRays(const glm::dvec3& p, const glm::dvec3& travel, const Shading& s, double penumbraDeg) {
    const glm::dvec3 c(0.0, kHeight, 0.0), u = -glm::normalize(travel);
    const double t = std::max(0.0, glm::dot(c - p, u));
    const double m = glm::length(p + t * u - c) - kRadius;
    const double hidden =
        m <= 0.0
            ? 1.0
            : (t > 0.0 ? 1.0 - std::clamp(m / (std::tan(glm::radians(penumbraDeg)) * t), 0.0, 1.0) : 0.0);
    return 1.0 - std::clamp((1.0 - expected(p, travel, s)) * hidden, 0.0, 1.0);
}

TEST(ProxyGLTest, RaysKeepTheHaloWhereTheBallHidesTheLight) {
    // Every floor pixel against the closed form above (tolerance 2e-3, as the listing's test: the
    // unprojected position's error moves v by ~1e-5). The default penumbra (10 degrees) and a narrow
    // one; the halo Listing 1.4 alone puts where the ray passes the ball by more than the penumbra is
    // gone (hundreds of pixels lit that the listing darkens).
    const std::string scene = writeScene(test::freshTestDir("proxy"), kOneLight, "[]");
    Shading s;
    s.offset = 2.0;
    const Frame listing = render(scene, "proxy:offset=2:modulate=on");
    for (const double penumbra : {10.0, 2.0}) {
        const Frame f = render(scene, "proxy:offset=2:penumbra=" + std::to_string(penumbra));
        double worst = 0.0;
        int hidden = 0, cleared = 0;
        for (size_t i = 0; i < f.world.size(); ++i) {
            if (!isFloor(f.world[i])) continue;
            const double v = f.visibility[i * 4];
            ASSERT_TRUE(std::isfinite(v));
            hidden += v < 0.99;
            cleared += v > 0.999 && listing.visibility[i * 4] < 0.99;
            worst = std::max(worst, std::abs(v - expectedRays(glm::dvec3(f.world[i]), kTravel, s, penumbra)));
        }
        std::cout << "penumbra " << penumbra << ": worst error " << worst << ", " << hidden << " shadowed, "
                  << cleared << " lit that Listing 1.4 alone darkens\n";
        EXPECT_LT(worst, 2e-3) << penumbra;
        EXPECT_GT(hidden, 200) << penumbra;
        EXPECT_GT(cleared, 500) << penumbra;
    }
}

TEST(ProxyGLTest, FalloffCutoffAndTheListingAsPrinted) {
    const std::string scene = writeScene(test::freshTestDir("proxy"), kOneLight, "[]");
    int shadowed = 0;
    Shading a;
    a.offset = 1.5, a.falloff = 2.5, a.shadow = 0.8, a.cutoff = 0.3;
    EXPECT_LT(worstError(render(scene, "proxy:offset=1.5:falloff=2.5:shadow=0.8:cutoff=0.3:modulate=on"), 0,
                         kTravel, a, &shadowed),
              2e-3);
    EXPECT_GT(shadowed, 500);
    Shading b = a;
    b.exponentOnFactor = true;
    EXPECT_LT(worstError(
                  render(scene,
                         "proxy:offset=1.5:falloff=2.5:shadow=0.8:cutoff=0.3:exponent_on=factor:modulate=on"),
                  0, kTravel, b, &shadowed),
              2e-3);
    Shading c;
    c.offset = 2.0, c.modulate = false;
    EXPECT_LT(worstError(render(scene, "proxy:offset=2:modulate=off"), 0, kTravel, c, &shadowed), 2e-3);
}

TEST(ProxyGLTest, OffsetZeroAndTinyAreFiniteAndLit) {
    // ProxyOffset 0 (the listing divides by it) and 1e-9: the volume shrinks to the surface, which no
    // floor point touches: every floor pixel lit, nothing NaN.
    const std::string scene = writeScene(test::freshTestDir("proxy"), kOneLight, "[]");
    for (const char* spec : {"proxy:offset=0", "proxy:offset=1e-9"}) {
        const Frame f = render(scene, spec);
        for (size_t i = 0; i < f.world.size(); ++i) {
            ASSERT_TRUE(std::isfinite(f.visibility[i * 4])) << spec;
            if (isFloor(f.world[i])) {
                EXPECT_EQ(f.visibility[i * 4], 1.0f) << spec;
            }
        }
    }
}

TEST(ProxyGLTest, EachColouredLightGetsItsOwnModulatedShadow) {
    const std::string scene =
        writeScene(test::freshTestDir("proxy"),
                   R"([{"type": "directional", "direction": [0.4, -1, 0.1], "color": [1, 0.5, 0.2]},
                                             {"type": "directional", "direction": [-0.6, -1, -0.3], "color": [0.2, 0.4, 1]}])",
                   "[]");
    const Frame f = render(scene, "proxy:offset=2:modulate=on");
    Shading s;
    s.offset = 2.0;
    int shadowed0 = 0, shadowed1 = 0;
    EXPECT_LT(worstError(f, 0, kTravel, s, &shadowed0), 2e-3);
    EXPECT_LT(worstError(f, 1, glm::dvec3(-0.6, -1.0, -0.3), s, &shadowed1), 2e-3);
    EXPECT_GT(shadowed0, 1000);
    EXPECT_GT(shadowed1, 1000);
    // The two shadows lean opposite ways: the channels must differ somewhere by a lot.
    double most = 0.0;
    for (size_t i = 0; i < f.world.size(); ++i)
        if (isFloor(f.world[i]))
            most = std::max<double>(most, std::abs(f.visibility[i * 4] - f.visibility[i * 4 + 1]));
    EXPECT_GT(most, 0.3);
}

TEST(ProxyGLTest, ColourBleedingOnlyWhenTheSceneAsksAndTowardsTheLight) {
    // Bleeding adds bleed * pow(base, falloff) * max(clamp(dot(-L, n), cutoff, 1), 0) * ball colour *
    // light colour to the floor's light, times the floor's albedo 0.5: compared with the same frame
    // without bleeding in 8-bit colour (tolerance 2/255: two roundings of the colour target).
    const std::string dir = test::freshTestDir("proxy");
    // A low light: the floor on its side of the ball faces the ball's lit half within the offset.
    const char* low = R"([{"type": "directional", "direction": [1, -0.3, 0]}])";
    const std::string plain = writeScene(dir, low, "[]");
    const Frame without = render(plain, "proxy:offset=2:bleed=0.8");
    EXPECT_EQ(without.permutation.find("PROXY_BLEED"), std::string::npos) << "compiled in unasked";
    const std::string asked = writeScene(test::freshTestDir("proxy"), low, R"(["colour_bleeding"])");
    const Frame with = render(asked, "proxy:offset=2:bleed=0.8");
    EXPECT_NE(with.permutation.find("PROXY_BLEED"), std::string::npos);
    EXPECT_EQ(with.visibility, without.visibility) << "bleeding must not change visibility";
    const glm::dvec3 ball(0.9, 0.2, 0.1), c(0.0, kHeight, 0.0),
        toLight = -glm::normalize(glm::dvec3(1.0, -0.3, 0.0));
    int judged = 0, tinted = 0;
    double worst = 0.0;
    for (size_t i = 0; i < with.world.size(); ++i) {
        if (!isFloor(with.world[i])) continue;
        const glm::dvec3 p(with.world[i]);
        const double d = std::max(glm::length(p - c) - kRadius, 0.0);
        const double base = 1.0 - std::min(d / 2.0, 1.0);
        const double towards = std::max(std::clamp(glm::dot(toLight, glm::normalize(p - c)), 0.0, 1.0), 0.0);
        for (int ch = 0; ch < 3; ++ch) {
            const double added = 0.5 * 0.8 * base * towards * ball[ch];
            const double got =
                (double(with.colour[i * 4 + size_t(ch)]) - double(without.colour[i * 4 + size_t(ch)])) /
                255.0;
            // Saturated pixels cannot show what was added.
            if (with.colour[i * 4 + size_t(ch)] == 255) continue;
            worst = std::max(worst, std::abs(got - added));
            ++judged;
            tinted += ch == 0 && got > 0.05;
        }
    }
    EXPECT_GT(judged, 10000);
    EXPECT_GT(tinted, 200) << "the red ball bleeds red onto the floor on the light's side";
    EXPECT_LT(worst, 2.5 / 255.0);
}

TEST(ProxyGLTest, GridOverflowIsCountedAndIndicesPass255) {
    // 300 balls crowded under the camera (all in the middle cells): with capacity 4 most cells overflow
    // (counted, not silent); with capacity 400 nothing does, and the image equals grid=off's (indices above
    // 255 reach the shader intact: the chapter's bytes would wrap them onto other proxies).
    const std::string dir = test::freshTestDir("proxy");
    std::string instances = R"({"mesh": "floor", "position": [0, 0, 0], "casts_shadow": false})";
    for (int i = 0; i < 300; ++i)
        instances += R"(, {"mesh": "ball", "position": [)" + std::to_string(-0.15 + 0.001 * i) + ", 0.6, " +
                     std::to_string(0.05 * std::sin(i * 0.7)) + R"(], "scale": 0.2})";
    const std::string path = dir + "/many.json";
    test::writeFile(path, R"({"name": "many",
  "meshes": [{"name": "ball", "generator": "sphere", "radius": 0.5, "tessellation": 8},
             {"name": "floor", "generator": "plane", "size": 6, "tessellation": 1}],
  "instances": [)" + instances +
                              R"(],
  "lights": [{"type": "directional", "direction": [0, -1, 0]}],
  "cameras": [{"name": "top", "eye": [0, 8, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fov": 50,
               "near": 0.5, "far": 50}]})");
    const Frame small = render(path, "proxy:offset=1:capacity=4");
    EXPECT_EQ(test::counter(small.counters, "proxies_in_view"), 300.0);
    EXPECT_GT(test::counter(small.counters, "grid_overflow"), 0.0);
    const Frame big = render(path, "proxy:offset=1:capacity=400");
    EXPECT_EQ(test::counter(big.counters, "grid_overflow"), 0.0);
    EXPECT_GT(test::counter(big.counters, "grid_max_per_cell"), 255.0)
        << "the case must put more than 255 in one cell";
    const Frame brute = render(path, "proxy:offset=1:grid=false");
    EXPECT_EQ(big.visibility, brute.visibility);
    EXPECT_NE(small.visibility, brute.visibility) << "overflowed cells must lose shadow (and say so)";
}

namespace {
/// Renders proxy:offset=2 through `camera` of tests/hard/scenes/proxy_ball.json, a camera `height` above
/// the ground at (x, 0, z) looking straight down (screen x = world +x, screen up = world -z, 50 degree
/// field), and compares every pixel's visibility with the closed form at its ground point (known from
/// the camera). Returns the largest error; `steepest` gets the largest step between neighbours, `span`
/// the closed form's range over the frame.
double closeUp(const char* camera, double x, double z, double height, double* steepest, double* range,
               double* span) {
    Harness h(
        test::quickConfig(std::string(SB_SOURCE_DIR) + "/tests/hard/scenes/proxy_ball.json", camera, kSize));
    ProxyGL t;
    t.properties().apply(TechniqueSpec::parse("proxy:offset=2:modulate=on").properties);
    h.prepare(t);
    h.renderFrame(t);
    const std::vector<float> vis = h.targets().readVisibilityRGBA32F();
    const double half = height * std::tan(glm::radians(25.0));
    const glm::dvec3 c(0.0, 1.5, 0.0), travel = glm::normalize(glm::dvec3(0.3, -1.0, 0.2));
    auto closed = [&](int px, int py) {
        const glm::dvec3 p(x + (2.0 * (px + 0.5) / kSize - 1.0) * half, 0.0,
                           z - (2.0 * (py + 0.5) / kSize - 1.0) * half);
        const double d = glm::length(p - c) - 1.0;
        return d >= 2.0 ? 1.0
                        : 1.0 - (1.0 - d / 2.0) * std::max(glm::dot(travel, glm::normalize(p - c)), 0.0);
    };
    double worst = 0.0, lo = 2.0, hi = -1.0, clo = 2.0, chi = -1.0;
    *steepest = 0.0;
    for (int py = 0; py < kSize; ++py)
        for (int px = 0; px < kSize; ++px) {
            const double v = vis[(size_t(py) * kSize + size_t(px)) * 4], e = closed(px, py);
            EXPECT_TRUE(std::isfinite(v));
            worst = std::max(worst, std::abs(v - e));
            lo = std::min(lo, v), hi = std::max(hi, v), clo = std::min(clo, e), chi = std::max(chi, e);
            if (px > 0)
                *steepest = std::max(*steepest, std::abs(v - vis[(size_t(py) * kSize + size_t(px - 1)) * 4]));
        }
    *range = hi - lo;
    *span = chi - clo;
    std::cout << camera << ": visibility " << lo << " .. " << hi << ", closed form " << clo << " .. " << chi
              << ", worst error " << worst << ", steepest step " << *steepest << "\n";
    return worst;
}
// The visibility target is RGBA16F: values in [0.5, 1) are stored 2^-11 = 4.88e-4 apart. Measured on
// llvmpipe, the conversion truncates (0.77016 and 0.99987 stored as the half below), so a stored value
// is within one step, not half a step, of what the shader computed; 5e-4 adds the float error.
constexpr double kStep = 5e-4;
} // namespace

TEST(ProxyGLTest, InfinitelySoftUpClose) {
    // The chapter's promise: no banding, no NaN however close the camera comes to the penumbra.
    // 1e-4 above the ground inside the halo: the frame spans 9e-5 units over which the visibility
    // changes by 3e-6, below the target's resolution: the image must be that one value, right to the
    // target's rounding (a distance computed with cancellation at this scale would be noise).
    double steepest = 0.0, range = 0.0, span = 0.0;
    EXPECT_LT(closeUp("closeup", 1.5, -1.0, 1e-4, &steepest, &range, &span), kStep);
    EXPECT_LE(steepest, 4.9e-4) << "at most one step of the target's resolution between neighbours";
    // 0.05 above the edge of the influence volume (d = offset at the frame's centre): continuity across
    // the boundary. The visibility climbs to 1 over half the frame and stays there; any step at the
    // boundary (Listing 1.3 is continuous there) or banding would exceed the even climb per pixel.
    const double k = std::sqrt(6.75) / std::hypot(1.5, 1.0);
    EXPECT_LT(closeUp("boundary", 1.5 * k, -1.0 * k, 0.05, &steepest, &range, &span), kStep);
    EXPECT_GT(range, 0.5 * span) << "the climb to 1 is in the image";
    EXPECT_GT(span, 10 * 4.9e-4) << "the case must span many steps of the target to show anything";
    EXPECT_LT(steepest, 3.0 * span / (0.5 * kSize) + 4.9e-4);
}

namespace {
// A caster standing on the floor inside a box proxy whose bottom face is the floor (y = 0 exactly):
// a ball of radius 0.3 at height 0.6 with a declared box proxy of half extents 1.2, 0.6, 1.2 about its
// centre, so the box spans y in [0, 1.2] and the floor around the ball, inside the box's footprint
// |x|, |z| <= 1.2, is a receiver lying on the proxy's bottom face (the fitted box of a teapot on the
// ground is this case).
constexpr double kHalf = 1.2;

std::string writeContactScene(const std::string& dir) {
    const std::string path = dir + "/contact.json";
    test::writeFile(path, R"({"name": "contact",
  "meshes": [{"name": "ball", "generator": "sphere", "radius": 0.3, "tessellation": 16,
              "proxies": [{"shape": "box", "size": [1.2, 0.6, 1.2]}]},
             {"name": "floor", "generator": "plane", "size": 6, "tessellation": 1}],
  "instances": [{"mesh": "floor", "position": [0, 0, 0], "casts_shadow": false, "color": [0.5, 0.5, 0.5]},
                {"mesh": "ball", "position": [0, 0.6, 0], "color": [0.9, 0.2, 0.1]}],
  "lights": [{"type": "directional", "direction": [0.4, -1, 0.1]}],
  "effects": [],
  "cameras": [{"name": "top", "eye": [0, 8, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fov": 50,
               "near": 0.5, "far": 50}]})");
    return path;
}

/// The closed form at floor point p (y = 0). Outside the footprint the chapter's halo: distance to the
/// box (its bottom edge), direction from there. Inside (the receiver lies on the bottom face, which it
/// never crosses): t = the distance within the floor to the nearest side face's line, the direction the
/// side normals weighted by 1 / t_f^2 (unit where one or two dominate, shrunk below half length), as
/// shaders/proxy/lit.frag documents; Listings 1.3 and 1.4 then as outside.
double contactExpected(double x, double z, double offset, bool modulate) {
    const glm::dvec3 travel = glm::normalize(kTravel);
    double dist;
    glm::dvec3 n(0.0);
    if (std::abs(x) > kHalf || std::abs(z) > kHalf) {
        const glm::dvec3 away(x - std::clamp(x, -kHalf, kHalf), 0.0, z - std::clamp(z, -kHalf, kHalf));
        dist = glm::length(away);
        n = away / dist;
    } else {
        const double t[4] = {kHalf - x, kHalf + x, kHalf - z, kHalf + z};
        const glm::dvec3 normals[4] = {{1, 0, 0}, {-1, 0, 0}, {0, 0, 1}, {0, 0, -1}};
        dist = *std::min_element(t, t + 4);
        glm::dvec3 weighted(0.0);
        double weights = 0.0;
        for (int f = 0; f < 4; ++f) {
            const double w = 1.0 / (t[f] * t[f] + 1e-30);
            weighted += w * normals[f];
            weights += w;
        }
        const glm::dvec3 w = weighted / weights;
        n = w / std::max(glm::length(w), 0.5);
    }
    if (dist > offset) return 1.0;
    double shadow = 1.0 - std::min(dist / offset, 1.0);
    if (modulate) shadow *= std::clamp(glm::dot(travel, n), 0.0, 1.0);
    return 1.0 - std::clamp(shadow, 0.0, 1.0);
}
} // namespace

TEST(ProxyGLTest, ReceiverOnAProxyFaceGetsTheHaloNotAHardShadow) {
    // Every floor pixel against the closed form, with and without Listing 1.4's modulation (tolerance
    // 2e-3 as above). Before, the whole footprint was distance 0: v = 1 - dot(travel, down) = 0.08
    // with modulation (0 without), under a caster the chapter says casts infinitely soft shadows.
    const std::string scene = writeContactScene(test::freshTestDir("proxy"));
    for (const bool modulate : {true, false}) {
        const std::string spec = modulate ? "proxy:offset=0.5:modulate=on" : "proxy:offset=0.5:modulate=off";
        const Frame f = render(scene, spec);
        double worst = 0.0;
        int footprint = 0, deepLit = 0, deep = 0;
        for (size_t i = 0; i < f.world.size(); ++i) {
            if (!isFloor(f.world[i])) continue;
            const double x = f.world[i].x, z = f.world[i].z, v = f.visibility[i * 4];
            worst = std::max(worst, std::abs(v - contactExpected(x, z, 0.5, modulate)));
            if (std::abs(x) > kHalf || std::abs(z) > kHalf) continue;
            ++footprint;
            // More than ProxyOffset inside the contact line the halo has faded: lit, as the reference
            // (nothing stands over that floor but the proxy) would have it.
            if (std::abs(x) < kHalf - 0.55 && std::abs(z) < kHalf - 0.55) ++deep, deepLit += v > 0.999;
        }
        EXPECT_LT(worst, 2e-3) << spec;
        EXPECT_GT(footprint, 3000) << spec << ": the case must show floor inside the footprint";
        EXPECT_GT(deep, 300) << spec;
        EXPECT_EQ(deepLit, deep) << spec << ": floor more than ProxyOffset inside the contact line is lit";
    }
}

TEST(ProxyGLTest, NoSeamAcrossTheContactLine) {
    // Along every pixel row and column that crosses the footprint's edge away from its corners (more
    // than 0.25 from them; at a corner Listing 1.4's direction turns through 90 degrees at distance 0
    // outside the box too), neighbouring floor pixels may differ by at most 0.05: the halo's steepest
    // legitimate step there is 0.039 per pixel (ProxyOffset 1, 0.039 units per pixel, the modulation
    // at most 1), plus the target's rounding. With modulation the seam before was a step of up to 0.92
    // (0.08 inside against 1 just outside the lit side; 0.63 outside the shadowed side); without it the
    // footprint was 0 throughout, continuous with the halo outside at distance 0 but a hard full
    // shadow (the test above).
    const std::string scene = writeContactScene(test::freshTestDir("proxy"));
    for (const char* spec : {"proxy:modulate=on", "proxy", "proxy:modulate=off"}) {
        const Frame f = render(scene, spec);
        auto at = [&](int x, int y) { return size_t(y) * kSize + size_t(x); };
        auto nearEdge = [&](const glm::vec4& w) {
            const double ax = std::abs(w.x), az = std::abs(w.z);
            const bool crossesX = std::abs(ax - kHalf) < 0.2 && az < kHalf - 0.25;
            const bool crossesZ = std::abs(az - kHalf) < 0.2 && ax < kHalf - 0.25;
            return crossesX || crossesZ;
        };
        double steepest = 0.0;
        int pairs = 0;
        for (int y = 0; y + 1 < kSize; ++y)
            for (int x = 0; x + 1 < kSize; ++x)
                for (const size_t j : {at(x + 1, y), at(x, y + 1)}) {
                    const size_t i = at(x, y);
                    if (!isFloor(f.world[i]) || !isFloor(f.world[j])) continue;
                    if (!nearEdge(f.world[i]) || !nearEdge(f.world[j])) continue;
                    ++pairs;
                    steepest =
                        std::max<double>(steepest, std::abs(f.visibility[i * 4] - f.visibility[j * 4]));
                }
        std::cout << spec << ": " << pairs << " neighbouring pairs across the contact line, steepest step "
                  << steepest << "\n";
        EXPECT_GT(pairs, 2000) << spec;
        EXPECT_LT(steepest, 0.05) << spec;
    }
}
