// `vsm` and `esm` against closed forms. The shadow of a sphere on a plane under a directional light is an
// exact ellipse (tests/ShadowMapGLTest.cpp): a ground point p is in it iff the ray from p towards the light
// passes within r of the centre. Every ground pixel is judged at its own world position (from the depth
// buffer): well inside the ellipse dark, well outside lit, with a band around the edge where the filter
// makes the visibility fractional; and ESM's interior against exp(-c (t - d_occ)) with d_occ the sphere's
// depth along the same ray. The lookups themselves (shaders/shadowmap/vsm.glsl, esm.glsl) are evaluated
// on moments computed here by hand, and the blur's weights against the Gaussian's integral.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "RenderedFrame.h"
#include "TestSupport.h"
#include "bench/lib/harness/Harness.h"
#include "core/Error.h"
#include "gl/backends/BackendRegistry.h"
#include "registry/TechniqueRegistry.h"
#include "scenes/LightFit.h"
#include "scenes/Math.h"
#include "techniques/ShadowMapProperties.h"
#include "techniques/gl/SeparableBlur.h"

using namespace sb;

namespace {

struct EllipseCase {
    const char* name;
    const char* spec; ///< technique with properties inline
    SubmitMode submit;
    /// Negative control: the judged interior must NOT all be dark (the test must see a shadow too light).
    bool expectTooLight = false;
};
void PrintTo(const EllipseCase& c, std::ostream* os) {
    *os << c.name;
}

const EllipseCase kEllipseCases[] = {
    {"vsm_default", "vsm", SubmitMode::Retained},
    {"vsm_blur9_instanced", "vsm:blur=9", SubmitMode::Instanced},
    {"vsm_no_background", "vsm:receiver_background=false", SubmitMode::Retained},
    {"vsm_bleed0_res256_displaylist", "vsm:bleed_reduction=0:resolution=256", SubmitMode::DisplayList},
    {"esm_default", "esm", SubmitMode::Retained},
    {"esm_exponent500_immediate", "esm:exponent=500", SubmitMode::Immediate},
    {"esm_blur0_no_background", "esm:blur=0:receiver_background=false", SubmitMode::Retained},
    {"esm_blur32_res256", "esm:blur=32:resolution=256", SubmitMode::Retained},
    {"evsm_default", "evsm", SubmitMode::Retained},
    {"evsm_components2_instanced", "evsm:components=2", SubmitMode::Instanced},
    {"msm_default", "msm", SubmitMode::Retained},
    {"msm_float_blur9", "msm:format=float:blur=9", SubmitMode::Retained},
    // exp(-2 (t - d_occ)) is 0.20..0.26 inside this ellipse (EsmInterior checks the values): too light.
    {"negative_esm_exponent2", "esm:exponent=2", SubmitMode::Retained, true},
};

/// The sphere of sphere_plane (the one caster): centre and radius from its geometry.
struct Sphere {
    glm::dvec3 centre{0.0};
    double radius = 0.0;
};

Sphere findSphere(const Scene& scene) {
    Sphere s;
    for (const Instance& i : scene.instances) {
        if (!i.castsShadow) continue;
        double meshRadius = 0.0;
        for (const glm::vec3& p : scene.meshes[i.mesh].positions)
            meshRadius = std::max(meshRadius, double(glm::length(p)));
        s.centre = glm::dvec3(i.model * glm::vec4(0, 0, 0, 1));
        s.radius = meshRadius * i.scale;
    }
    return s;
}

/// Distance from the sphere's centre to the ray from p towards the light, minus the radius: negative inside
/// the shadow ellipse (world units perpendicular to the light).
double shadowMargin(const glm::dvec3& p, const glm::dvec3& toLight, const Sphere& s) {
    const glm::dvec3 pc = s.centre - p;
    const double t = glm::dot(pc, toLight);
    if (t <= 0.0) return 1e9;
    return glm::length(pc - t * toLight) - s.radius;
}

/// The sphere's point nearest the light on the ray from p towards it (p must be in the shadow).
glm::dvec3 occluderPoint(const glm::dvec3& p, const glm::dvec3& toLight, const Sphere& s) {
    const glm::dvec3 pc = s.centre - p;
    const double along = glm::dot(pc, toLight);
    const double off2 = glm::dot(pc, pc) - along * along;
    return p + (along + std::sqrt(std::max(0.0, s.radius * s.radius - off2))) * toLight;
}

/// Window depth of the orthographic light camera the shadow maps are fitted with (scenes/LightFit.h):
/// 0.5 z_clip + 0.5, which is linear along the light.
double windowDepth(const glm::dmat4& lightViewProj, const glm::dvec3& p) {
    return 0.5 * (lightViewProj * glm::dvec4(p, 1.0)).z + 0.5;
}

/// The depth range sphere_plane covers inside the map's frustum (what the maps rescale to [0, 1]),
/// worked out here for this scene: the sphere's box lies inside the frustum (the fit encloses the casters),
/// and the ground y = 0 meets it in the parallelogram where the frustum's four side edges cross the plane;
/// the range is that of the box's 8 corners and those 4 points. The map's frustum is the fit's widened by
/// `widen` (resolution / (resolution - 2 margin), FilterableShadowMaps.h): its edges at clip x, y = +-widen.
glm::dvec2 depthRangeInMap(const glm::dmat4& lightViewProj, const Sphere& s, double widen) {
    glm::dvec2 range(1e9, -1e9);
    auto add = [&](const glm::dvec3& p) {
        const double z = windowDepth(lightViewProj, p);
        range = {std::min(range.x, z), std::max(range.y, z)};
    };
    for (int i = 0; i < 8; ++i)
        add(s.centre + s.radius * glm::dvec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1));
    const glm::dmat4 inverse = glm::inverse(lightViewProj);
    for (int i = 0; i < 4; ++i) {
        const glm::dvec2 xy = widen * glm::dvec2(i & 1 ? 1 : -1, i & 2 ? 1 : -1);
        glm::dvec4 a = inverse * glm::dvec4(xy, -1.0, 1.0), b = inverse * glm::dvec4(xy, 1.0, 1.0);
        const glm::dvec3 p = glm::dvec3(a) / a.w, q = glm::dvec3(b) / b.w;
        add(p + (p.y / (p.y - q.y)) * (q - p)); // where the edge crosses y = 0
    }
    return range;
}

class MomentEllipse : public ::testing::TestWithParam<EllipseCase> {};

TEST_P(MomentEllipse, DarkInsideLitOutsideFiniteEverywhere) {
    const EllipseCase& tc = GetParam();
    constexpr int kSize = 384;
    RunConfig cfg = test::quickConfig("sphere_plane", "top", kSize, tc.submit);
    cfg.sceneOptions.tessellation = 64; // polygonal silhouette within r(1 - cos(pi/64)) = 1.2e-3 r
    cfg.sceneOptions.lightType = LightType::Directional;
    Harness h(cfg);
    std::unique_ptr<GlTechnique> t = TechniqueRegistry::create(TechniqueSpec::parse(tc.spec));
    const test::RenderedFrame f = test::renderOnce(h, *t);
    const Scene& scene = h.scene();
    const Sphere sphere = findSphere(scene);
    ASSERT_GT(sphere.radius, 0.0);
    const glm::dvec3 toLight = -glm::normalize(glm::dvec3(scene.lights[0].direction));

    // The band around the ellipse's edge, in world units perpendicular to the light. A lookup reads the
    // map's texels within a square of half-width (blur / 2) + 1 texels around its position (the blur's
    // taps |k| <= blur / 2 along each axis, then the bilinear footprint's one texel), so beyond
    // sqrt(2) ((blur / 2) + 1) texels from the edge (the square's corner) the filter sees only the sphere
    // or only the ground, and the answer is the unfiltered one. Plus half a texel for where the
    // rasteriser puts the silhouette, the screen pixel's footprint on the ground (added per pixel) and the
    // polygonal sphere's silhouette error.
    const glm::mat4 lightVP = fitLightViewProjection(scene, scene.lights[0]);
    auto rowLength = [&](int r) {
        return glm::length(glm::vec3(lightVP[0][r], lightVP[1][r], lightVP[2][r]));
    };
    const double orthoWidth = 2.0 / std::min(rowLength(0), rowLength(1));
    const int res = int(t->properties().getInt("resolution"));
    const int blurRadius = int(t->properties().getInt("blur")) / 2;
    // The fit fills the inner res - 2 (blurRadius + 1) texels (FilterableShadowMaps.h, "The margin").
    const double texel = orthoWidth / (res - 2 * (blurRadius + 1));
    const double band =
        texel * (std::sqrt(2.0) * (blurRadius + 1) + 0.5) + sphere.radius * (1.0 - std::cos(M_PI / 64.0));

    size_t notFinite = 0, outOfRange = 0;
    for (float v : f.visibility) {
        notFinite += !std::isfinite(v);
        outOfRange += std::isfinite(v) && (v < 0.0f || v > 1.0f);
    }
    EXPECT_EQ(notFinite, 0u) << "NaN/Inf in the visibility target";
    EXPECT_EQ(outOfRange, 0u) << "visibility outside [0, 1]";

    int ground = 0, judged = 0, inside = 0, outside = 0, wrong = 0;
    float darkestOutside = 1.0f, brightestInside = 0.0f;
    for (int y = 1; y < kSize - 1; ++y)
        for (int x = 1; x < kSize - 1; ++x) {
            const size_t i = size_t(y) * kSize + size_t(x);
            if (f.world[i].w == 0.0f || std::abs(f.world[i].y) > 1e-2f) continue; // ground pixels only
            ++ground;
            const double footprint = glm::length(glm::vec3(f.world[i + 1]) - glm::vec3(f.world[i]));
            const double margin = shadowMargin(glm::dvec3(f.world[i]), toLight, sphere);
            if (std::abs(margin) <= band + footprint) continue; // the filtered edge: any value is right
            ++judged;
            const float v = f.visibility[i * 4];
            const bool ok = margin < 0.0 ? v < 0.1f : v > 0.9f;
            if (margin < 0.0) {
                ++inside;
                brightestInside = std::max(brightestInside, v);
            } else {
                ++outside;
                darkestOutside = std::min(darkestOutside, v);
            }
            if (!ok && ++wrong <= 5 && !tc.expectTooLight)
                ADD_FAILURE() << "pixel (" << x << "," << y << ") margin " << margin << " visibility " << v;
        }
    std::cout << tc.name << ": band " << band << " (" << band / texel << " texels), judged " << judged
              << " of " << ground << ", brightest interior " << brightestInside << ", darkest exterior "
              << darkestOutside << "\n";
    // The ellipse must be well in view and the band must leave most of the ground judged.
    EXPECT_GT(ground, kSize * kSize / 4);
    EXPECT_GT(inside, 500) << "the judged interior hardly covers any pixel";
    EXPECT_GT(judged, ground * 9 / 10) << "the band (" << band << " world units) swallowed the image";
    if (tc.expectTooLight) {
        EXPECT_GT(wrong, inside / 2) << "negative control: the shadow is too light and the test must see it";
        EXPECT_GT(brightestInside, 0.1f);
        return;
    }
    EXPECT_EQ(wrong, 0) << "brightest judged interior " << brightestInside << ", darkest judged exterior "
                        << darkestOutside << " (band " << band << ")";
}

INSTANTIATE_TEST_SUITE_P(Moments, MomentEllipse, ::testing::ValuesIn(kEllipseCases),
                         [](const auto& p) { return std::string(p.param.name); });

// ESM's interior is not "dark", it is exp(-c (t - d_occ)) (Annen et al. 2008, equation 5): at a small
// exponent the value is far from 0 and must be that value. Both depths are computed here from the fitted
// light camera, the exact sphere and the depth range the map covers (depthRangeInMap). Tolerance: 0.01
// absolute (half-float target 5e-4 at these values; the filter's averaging of the sphere's depth over a few
// 2 mm texels well inside the silhouette, where exp's convexity adds c Var / 2, ~1e-6) plus 3% relative
// (the polygonal sphere's depth error, 1.2e-3 r = 1.2e-3 world units, ~1e-4 of the normalised range of
// ~10 units: c 1e-4 relative). Measured worst error 1.3e-4 at c = 2, 7e-6 at c = 8.
class EsmInterior : public ::testing::TestWithParam<int> {};

TEST_P(EsmInterior, MatchesExponentialOfDepthDifference) {
    const int c = GetParam();
    constexpr int kSize = 256;
    RunConfig cfg = test::quickConfig("sphere_plane", "top", kSize);
    cfg.sceneOptions.tessellation = 64;
    Harness h(cfg);
    std::unique_ptr<GlTechnique> t =
        TechniqueRegistry::create(TechniqueSpec::parse("esm:exponent=" + std::to_string(c)));
    const test::RenderedFrame f = test::renderOnce(h, *t);
    const Scene& scene = h.scene();
    const Sphere sphere = findSphere(scene);
    const glm::dvec3 toLight = -glm::normalize(glm::dvec3(scene.lights[0].direction));
    const glm::dmat4 lightVP(fitLightViewProjection(scene, scene.lights[0]));
    // Default resolution 1024 and blur 3: a margin of 3 / 2 + 1 = 2 texels.
    const glm::dvec2 range = depthRangeInMap(lightVP, sphere, 1024.0 / (1024.0 - 4.0));
    ASSERT_GT(range.y - range.x, 1e-3);
    auto depth = [&](const glm::dvec3& p) {
        return (windowDepth(lightVP, p) - range.x) / (range.y - range.x);
    };
    int judged = 0, wrong = 0;
    double minExpected = 1.0, maxExpected = 0.0, worst = 0.0;
    for (size_t i = 0; i < f.world.size(); ++i) {
        if (f.world[i].w == 0.0f || std::abs(f.world[i].y) > 1e-2f) continue;
        const glm::dvec3 p(f.world[i]);
        if (shadowMargin(p, toLight, sphere) > -0.1 * sphere.radius) continue; // well inside only
        const double expected = std::exp(-c * (depth(p) - depth(occluderPoint(p, toLight, sphere))));
        minExpected = std::min(minExpected, expected);
        maxExpected = std::max(maxExpected, expected);
        ++judged;
        const double got = f.visibility[i * 4];
        worst = std::max(worst, std::abs(got - expected));
        if (std::abs(got - expected) > 0.01 + 0.03 * expected && ++wrong <= 5)
            ADD_FAILURE() << "world " << p.x << "," << p.z << ": visibility " << got << ", expected "
                          << expected;
    }
    std::cout << "c = " << c << ": depth range " << range.x << ".." << range.y << ", " << judged
              << " judged, expected " << minExpected << ".." << maxExpected << ", worst error " << worst
              << "\n";
    EXPECT_GT(judged, 300);
    EXPECT_EQ(wrong, 0) << "expected values from " << minExpected << " to " << maxExpected;
    if (c == 2) {
        EXPECT_GT(minExpected, 0.1) << "the small exponent's interior must be visibly lit";
    }
}

INSTANTIATE_TEST_SUITE_P(Moments, EsmInterior, ::testing::Values(2, 8));

// A spot light exercises the distance-based depth: the ground under the sphere is shadowed, the ground
// far from its projection but inside the cone lit (the band: perspective texels grow with distance, as in
// ShadowMapGLTest's spot case).
class MomentSpot : public ::testing::TestWithParam<const char*> {};

TEST_P(MomentSpot, ShadowsTheGroundUnderTheSphere) {
    RunConfig cfg = test::quickConfig("sphere_plane", "top", 256);
    cfg.sceneOptions.lightType = LightType::Spot;
    Harness h(cfg);
    std::unique_ptr<GlTechnique> t = TechniqueRegistry::create(TechniqueSpec::parse(GetParam()));
    const test::RenderedFrame f = test::renderOnce(h, *t);
    const Scene& scene = h.scene();
    const Light& light = scene.lights[0];
    ASSERT_EQ(light.type, LightType::Spot);
    const Sphere sphere = findSphere(scene);
    int checked = 0, wrong = 0, shadowed = 0;
    for (size_t i = 0; i < f.world.size(); ++i) {
        if (f.world[i].w == 0.0f || std::abs(f.world[i].y) > 1e-2f) continue;
        const glm::dvec3 p(f.world[i]);
        const glm::dvec3 toL = glm::normalize(glm::dvec3(light.position) - p);
        if (glm::dot(-toL, glm::normalize(glm::dvec3(light.direction))) <
            std::cos(glm::radians(light.spotOuterDeg)) + 0.02)
            continue; // outside the cone: unlit whatever the map says
        const double margin = shadowMargin(p, toL, sphere);
        if (std::abs(margin) < 0.1 * sphere.radius) continue;
        ++checked;
        shadowed += margin < 0.0;
        wrong += (margin < 0.0) != (f.visibility[i * 4] < 0.5f);
    }
    EXPECT_GT(checked, 1000);
    EXPECT_GT(shadowed, 100);
    EXPECT_EQ(wrong, 0);
}

INSTANTIATE_TEST_SUITE_P(Moments, MomentSpot,
                         ::testing::Values("vsm", "esm", "esm:exponent=500", "evsm", "msm"),
                         [](const auto& p) {
                             std::string n = p.param;
                             std::replace_if(
                                 n.begin(), n.end(), [](char ch) { return !std::isalnum(ch); }, '_');
                             return n;
                         });

// The receiver background (FilterableShadowMaps.h) draws non-casters into the map, the farthest per
// texel: a non-caster floating over the ground must still shadow nothing. A plate (casts_shadow false) at
// height 2 over x in [4, 6], |z| < 1, light along (0.5, -1, 0): were it a caster, its shadow would cover
// the ground x in [5, 7], of which x in [6, 7] is visible from above. Two casting spheres at x = 0 and
// x = 10 stretch the map over the plate. Judged: that ground strip (0.1 inside each side) and the plate's
// top, all lit; and the ground under the spheres' shadows dark, so the map is in use.
TEST(MomentShadows, NonCastersInTheBackgroundShadowNothing) {
    const std::string dir = test::freshTestDir("moments_noncaster");
    const std::string scene = dir + "/noncaster.json";
    test::writeFile(scene, R"({
  "name": "noncaster",
  "meshes": [
    {"name": "sphere", "generator": "sphere", "radius": 1, "tessellation": 32},
    {"name": "plate", "generator": "box", "half_extent": [1, 0.02, 1], "tessellation": 1},
    {"name": "ground", "generator": "plane", "size": 40, "tessellation": 16}
  ],
  "instances": [
    {"mesh": "ground", "position": [0, 0, 0], "casts_shadow": false},
    {"mesh": "plate", "position": [5, 2, 0], "casts_shadow": false},
    {"mesh": "sphere", "position": [0, 3, 0]},
    {"mesh": "sphere", "position": [10, 3, 0]}
  ],
  "lights": [{"type": "directional", "direction": [0.5, -1, 0]}],
  "cameras": [{"name": "top", "eye": [6, 30, 0], "target": [6, 0, 0], "up": [0, 0, -1], "fov": 40,
               "near": 1, "far": 100}],
  "effects": ["hard_shadows"]
})");
    for (const char* spec :
         {"vsm", "esm", "esm:exponent=500", "vsm:receiver_background=false", "evsm", "msm"}) {
        const test::RenderedFrame f = test::renderSpec(scene, "top", 256, spec);
        int strip = 0, stripDark = 0, plate = 0, plateDark = 0, sphereShadow = 0, sphereShadowLit = 0;
        for (size_t i = 0; i < f.world.size(); ++i) {
            if (f.world[i].w == 0.0f) continue;
            const glm::vec3 p(f.world[i]);
            const float v = f.visibility[i * 4];
            if (std::abs(p.y) < 1e-2f && p.x > 6.1f && p.x < 6.9f && std::abs(p.z) < 0.9f) {
                ++strip;
                stripDark += v < 0.9f;
            } else if (std::abs(p.y - 2.02f) < 1e-2f && std::abs(p.x - 5.0f) < 0.9f && std::abs(p.z) < 0.9f) {
                ++plate;
                plateDark += v < 0.9f;
            } else if (std::abs(p.y) < 1e-2f && glm::length(glm::vec2(p.x - 1.5f, p.z)) < 0.5f) {
                ++sphereShadow; // around the first sphere's shadow centre (0, 3, 0) + 3 (0.5, 0)
                sphereShadowLit += v > 0.1f;
            }
        }
        EXPECT_GT(strip, 200) << spec;
        EXPECT_GT(plate, 200) << spec;
        EXPECT_GT(sphereShadow, 50) << spec;
        EXPECT_EQ(stripDark, 0) << spec << ": the non-casting plate shadowed the ground";
        EXPECT_EQ(plateDark, 0) << spec << ": the plate's own top is lit";
        EXPECT_EQ(sphereShadowLit, 0) << spec << ": the spheres' shadows must be there";
    }
}

TEST(MomentShadows, PointLightIsRefusedNamingTheOmniTechniques) {
    for (const char* name : {"vsm", "esm", "evsm", "msm"}) {
        RunConfig cfg = test::quickConfig("sphere_plane", "top", 64);
        cfg.sceneOptions.lightType = LightType::Point;
        Harness h(cfg);
        std::unique_ptr<GlTechnique> t = TechniqueRegistry::create(name);
        try {
            h.prepare(*t);
            ADD_FAILURE() << name << ": point light accepted";
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), ExitCode::Unsupported) << name;
            const std::string what = e.what();
            EXPECT_NE(what.find("point light"), std::string::npos) << what;
            EXPECT_NE(what.find("cubemap"), std::string::npos) << what;
            EXPECT_NE(what.find("paraboloid"), std::string::npos) << what;
        }
    }
}

TEST(MomentShadows, CountersSayWhatWasRenderedAndBlurred) {
    // sphere_plane: one light, one caster (the sphere), which its fitted map contains.
    const auto blurred = test::renderSpec("sphere_plane", "top", 64, "vsm:resolution=256:blur=5");
    EXPECT_EQ(test::counter(blurred.counters, "shadow_map_texels"), 256.0 * 256.0);
    EXPECT_EQ(test::counter(blurred.counters, "blur_texels"), 2.0 * 256.0 * 256.0); // two passes
    EXPECT_EQ(test::counter(blurred.counters, "casters_culled"), 0.0);
    EXPECT_GT(test::counter(blurred.counters, "triangles"), 0.0);
    const auto unblurred = test::renderSpec("sphere_plane", "top", 64, "esm:resolution=128:blur=1");
    EXPECT_EQ(test::counter(unblurred.counters, "shadow_map_texels"), 128.0 * 128.0);
    EXPECT_EQ(test::counter(unblurred.counters, "blur_texels"), 0.0) << "a 1-texel kernel is no blur";
    // Depth pass: the sphere, and the ground as the receiver background; lighting: both. Without the
    // background one draw fewer.
    const auto without = test::renderSpec("sphere_plane", "top", 64, "esm:receiver_background=false");
    EXPECT_EQ(test::counter(unblurred.counters, "draw_calls"), 4.0);
    EXPECT_EQ(test::counter(without.counters, "draw_calls"), 3.0);
}

TEST(MomentShadows, BlurWeightsAreTheTruncatedGaussiansIntegralPerTexel) {
    EXPECT_EQ(SeparableBlur::weights(0), std::vector<float>{1.0f});
    EXPECT_EQ(SeparableBlur::weights(1), std::vector<float>{1.0f});
    // Width 3: sigma 0.75, support [-1.5, 1.5], taps 0 and +-1 each a whole texel. By hand:
    // erf(0.5 / (0.75 sqrt 2)) = erf(0.4714) = 0.49501, erf(1.5 / (0.75 sqrt 2)) = erf(1.4142) = 0.95450;
    // centre 0.49501, each side (0.95450 - 0.49501) / 2 = 0.22975, normalised by 0.95450.
    const std::vector<float> w3 = SeparableBlur::weights(3);
    ASSERT_EQ(w3.size(), 2u);
    EXPECT_NEAR(w3[0], 0.49501 / 0.95450, 2e-5);
    EXPECT_NEAR(w3[1], 0.22975 / 0.95450, 2e-5);
    // Width 2: sigma 0.5, support [-1, 1]: the outer taps get [0.5, 1] only.
    // erf(0.5 / (0.5 sqrt 2)) = erf(0.7071) = 0.68269, erf(1 / (0.5 sqrt 2)) = erf(1.4142) = 0.95450.
    const std::vector<float> w2 = SeparableBlur::weights(2);
    ASSERT_EQ(w2.size(), 2u);
    EXPECT_NEAR(w2[0], 0.68269 / 0.95450, 2e-5);
    EXPECT_NEAR(w2[1], (0.95450 - 0.68269) / 2 / 0.95450, 2e-5);
    for (int width : {2, 3, 9, 16, ShadowMapProperties::kMaxBlurWidth}) {
        const std::vector<float> w = SeparableBlur::weights(width);
        EXPECT_EQ(int(w.size()), width / 2 + 1);
        double sum = w[0];
        for (size_t k = 1; k < w.size(); ++k) {
            sum += 2.0 * w[k];
            EXPECT_LT(w[k], w[k - 1]) << "width " << width << ": a Gaussian falls off";
            EXPECT_GT(w[k], 0.0f);
        }
        EXPECT_NEAR(sum, 1.0, 1e-6) << "width " << width;
    }
}

// The lookups of shaders/shadowmap/vsm.glsl and esm.glsl, run on the GL and compared with values worked
// out by hand: a small program whose pixel i evaluates case i. The shaders are compiled through the real
// preprocessor from a folder holding this test's fragment stage beside links to shaders/shadowmap and
// shaders/common.
class MomentLookups : public ::testing::Test {
protected:
    struct VsmCase {
        glm::vec4 moments; ///< M1, M2, t, minVariance
        float amount;      ///< bleeding reduction
        double expected;
        const char* why;
    };
    struct EsmCase {
        glm::vec4 depths, weights;
        float t, c;
        double expected;
        const char* why;
    };
    static constexpr int kCases = 8;

    static std::vector<glm::vec4> evaluate(const std::vector<VsmCase>& vsm, const std::vector<EsmCase>& esm) {
        auto context = createContext(ContextOptions{});
        namespace fs = std::filesystem;
        const fs::path root = test::freshTestDir("moment_lookups");
        fs::create_directory_symlink(fs::path(SB_SOURCE_DIR) / "shaders" / "shadowmap", root / "shadowmap");
        fs::create_directory_symlink(fs::path(SB_SOURCE_DIR) / "shaders" / "common", root / "common");
        fs::create_directories(root / "test");
        test::writeFile((root / "test" / "lookups.frag").string(), R"(
#include "shadowmap/vsm.glsl"
#include "shadowmap/esm.glsl"
layout(location = 0) uniform vec4 uMoments[8];  // M1, M2, t, minVariance
layout(location = 8) uniform float uAmount[8];
layout(location = 16) uniform vec4 uDepths[8];
layout(location = 24) uniform vec4 uWeights[8];
layout(location = 32) uniform vec2 uTc[8];      // t, c
layout(location = 0) out vec4 oValue;
void main() {
    int i = int(gl_FragCoord.x);
    vec4 m = uMoments[i];
    oValue = vec4(reduceLightBleeding(chebyshevUpperBound(m.xy, m.z, m.w), uAmount[i]),
                  exponentialVisibility(uDepths[i], uWeights[i], uTc[i].x, uTc[i].y), 0.0, 1.0);
}
)");
        ProgramCache programs(root.string());
        const Program& program = programs.get({"common/fullscreen.vert", "test/lookups.frag", ""}, {});
        GLuint texture = 0, fbo = 0, vao = 0;
        glCreateTextures(GL_TEXTURE_2D, 1, &texture);
        glTextureStorage2D(texture, 1, GL_RGBA32F, kCases, 1);
        glCreateFramebuffers(1, &fbo);
        glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, texture, 0);
        glCreateVertexArrays(1, &vao);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glViewport(0, 0, kCases, 1);
        program.use();
        for (size_t i = 0; i < vsm.size(); ++i) {
            glUniform4fv(GLint(i), 1, &vsm[i].moments.x);
            glUniform1f(GLint(8 + i), vsm[i].amount);
        }
        for (size_t i = 0; i < esm.size(); ++i) {
            glUniform4fv(GLint(16 + i), 1, &esm[i].depths.x);
            glUniform4fv(GLint(24 + i), 1, &esm[i].weights.x);
            glUniform2f(GLint(32 + i), esm[i].t, esm[i].c);
        }
        glBindVertexArray(vao);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        std::vector<glm::vec4> out(kCases);
        glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, GLsizei(out.size() * sizeof(glm::vec4)), out.data());
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
        glDeleteVertexArrays(1, &vao);
        glDeleteFramebuffers(1, &fbo);
        glDeleteTextures(1, &texture);
        return out;
    }
};

TEST_F(MomentLookups, ChebyshevAndExponentialOnHandComputedInputs) {
    // Two depths 0.2 (fraction f = 0.3) and 0.6 (0.7): M1 = 0.48, M2 = 0.3 * 0.04 + 0.7 * 0.36 = 0.264,
    // sigma^2 = 0.264 - 0.2304 = 0.0336. A receiver at the deeper depth t = 0.6: t - M1 = 0.12, so
    // p_max = 0.0336 / (0.0336 + 0.0144) = 0.7 = 1 - f, the exact lit fraction (the bound is tight there).
    const std::vector<VsmCase> vsm = {
        {{0.48f, 0.264f, 0.6f, 0.0f}, 0.0f, 0.7, "two depths, receiver at the deeper: tight"},
        // The same at t = 0.5 (just behind the mean): 0.0336 / (0.0336 + 0.0004) = 0.98824: light bleeding,
        // the true lit fraction there is 0.7 too.
        {{0.48f, 0.264f, 0.5f, 0.0f}, 0.0f, 0.0336 / 0.034, "receiver near the mean: the bound bleeds"},
        {{0.48f, 0.264f, 0.48f, 0.0f}, 0.0f, 1.0, "t <= M1: lit"},
        // Zero variance, t 0.01 behind: minVariance 1e-4 gives 1e-4 / (1e-4 + 1e-4) = 0.5.
        {{0.5f, 0.25f, 0.51f, 1e-4f}, 0.0f, 0.5, "the variance clamp"},
        // M2 < M1^2 (rounding) and no clamp: variance 0, shadowed.
        {{0.5f, 0.2499f, 0.6f, 0.0f}, 0.0f, 0.0, "negative variance clamps to 0"},
        // Bleeding reduction: linstep(0.4, 1, 0.7) = 0.5; linstep(0.4, 1, 0.3) = 0.
        {{0.48f, 0.264f, 0.6f, 0.0f}, 0.4f, 0.5, "reduction rescales (amount, 1]"},
        // p_max 0.3: two depths f = 0.7 at 0.2, 0.3 at 0.6: M1 = 0.32, M2 = 0.7 * 0.04 + 0.3 * 0.36 = 0.136.
        {{0.32f, 0.136f, 0.6f, 0.0f}, 0.4f, 0.0, "reduction cuts the tail below amount"},
        {{0.32f, 0.136f, 0.6f, 0.0f}, 0.0f, 0.3, "the same without reduction: 1 - f"},
    };
    const std::vector<EsmCase> esm = {
        // Half the taps at the receiver's depth, half 0.4 in front: 0.5 + 0.5 exp(-0.4 c).
        {{0.2f, 0.2f, 0.6f, 0.6f},
         {0.25f, 0.25f, 0.25f, 0.25f},
         0.6f,
         10.0f,
         0.5 + 0.5 * std::exp(-4.0),
         "c = 10"},
        {{0.2f, 0.2f, 0.6f, 0.6f}, {0.25f, 0.25f, 0.25f, 0.25f}, 0.6f, 500.0f, 0.5, "c = 500: exp(-200) = 0"},
        {{0.2f, 0.2f, 0.6f, 0.6f},
         {0.25f, 0.25f, 0.25f, 0.25f},
         0.2f,
         500.0f,
         1.0,
         "receiver in front: exp(+200) would overflow, clamps to 1"},
        {{0.2f, 0.2f, 0.2f, 0.2f},
         {0.25f, 0.25f, 0.25f, 0.25f},
         0.9f,
         500.0f,
         0.0,
         "deep shadow: exp(-350) underflows to 0"},
        // A weight-0 tap far behind: exp(500 * 0.5) = Inf times weight 0 would be NaN.
        {{1.0f, 0.2f, 0.2f, 0.2f},
         {0.0f, 1.0f / 3, 1.0f / 3, 1.0f / 3},
         0.5f,
         500.0f,
         0.0,
         "weight-0 tap at depth 1"},
        // Bilinear weights 0.1 / 0.9 between 0.3 and the receiver's 0.5 at c = 40: 0.9 + 0.1 exp(-8).
        {{0.3f, 0.5f, 0.5f, 0.5f},
         {0.1f, 0.9f, 0.0f, 0.0f},
         0.5f,
         40.0f,
         0.9 + 0.1 * std::exp(-8.0),
         "uneven weights"},
        {{0.5f, 0.5f, 0.5f, 0.5f}, {0.25f, 0.25f, 0.25f, 0.25f}, 0.5f, 500.0f, 1.0, "on the occluder: lit"},
        {{0.5f, 0.5f, 0.5f, 0.5f},
         {0.25f, 0.25f, 0.25f, 0.25f},
         0.501f,
         500.0f,
         std::exp(-0.5),
         "1e-3 behind at c = 500: exp(-0.5)"},
    };
    ASSERT_EQ(vsm.size(), size_t(kCases));
    ASSERT_EQ(esm.size(), size_t(kCases));
    const std::vector<glm::vec4> got = evaluate(vsm, esm);
    // Float32 arithmetic on inputs rounded to float: 1e-4 covers the rounding of M2 - M1^2 (~1e-7 of
    // 0.0336) carried through the quotient; the ESM 1e-3 case's t is 0.501f, whose rounding moves
    // exp(-500 (t - 0.5)) by 500 * 3e-8 relative.
    for (int i = 0; i < kCases; ++i) {
        EXPECT_TRUE(std::isfinite(got[size_t(i)].x) && std::isfinite(got[size_t(i)].y)) << i;
        EXPECT_NEAR(got[size_t(i)].x, vsm[size_t(i)].expected, 1e-4) << "vsm " << vsm[size_t(i)].why;
        EXPECT_NEAR(got[size_t(i)].y, esm[size_t(i)].expected, 1e-4) << "esm " << esm[size_t(i)].why;
    }
}

} // namespace
