// Shadow-map texels per screen pixel (bench/lib/measure/TexelDensity.h) through each family's light-space
// mapping (techniques/MapTexels.h), against closed forms worked out by hand:
//  - an orthographic map of a directional light straight down, fitted to a caster of known size (the
//    fit's documented padding: scenes/LightFit.h), under an orthographic camera straight down: t =
//    (texels per world unit) / (pixels per world unit), a constant; under a camera tilted by 60 degrees
//    a pixel's footprint grows by 1 / cos 60 along the tilt, so t grows by sqrt(2);
//  - a map of fixed size (the sphere fit: the same square from every light direction) under a light tilted
//    by 40 degrees: a texel's footprint on the ground grows by 1 / cos 40, t falls by sqrt(cos 40);
//  - a perspective camera straight down onto a plane parallel to its image: every pixel's footprint is
//    2 H tan(fov / 2) / W, on the axis and off it;
//  - a point light's cube face below it (a 90-degree perspective camera onto a parallel plane: res / 2H
//    texels per unit everywhere on the face) and its paraboloid half (the nonlinear projection: radial
//    and tangential scales of tan(alpha / 2) at the angle alpha from the axis);
//  - cascaded: a tilted perspective camera over a ground, tight fits, the sample's cascade the one whose
//    split interval holds its view depth, each cascade's box the light-space bounds of its slice's
//    eight corners, and the pixel's footprint the perspective closed form f^2 cos(beta) / (r^2 cos^3(alpha)).
// Under 0.1 s.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "bench/golden/AccuracyBounds.h"
#include "bench/lib/measure/TexelDensity.h"
#include "registry/TechniqueRegistry.h"
#include "scenes/LightFit.h"
#include "techniques/FlatLightFits.h"
#include "techniques/PropertySet.h"
#include "techniques/shadowmap/Cascaded.h"
#include "techniques/shadowmap/CascadedMaps.h"
#include "techniques/shadowmap/OmniLightSet.h"

using namespace sb;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kImage = 256; // pixels a side
constexpr int kMap = 1024;  // texels a side

/// Adds a box [lo, hi] as a mesh of its 8 corners (the fits and culling read bounds only).
void addBox(Scene& scene, const glm::vec3& lo, const glm::vec3& hi, bool casts, bool receives = true) {
    Mesh mesh;
    mesh.name = "box" + std::to_string(scene.meshes.size());
    for (int i = 0; i < 8; ++i)
        mesh.positions.emplace_back(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
    mesh.normals.assign(8, glm::vec3(0, 1, 0));
    Instance instance;
    instance.mesh = uint32_t(scene.meshes.size());
    instance.castsShadow = casts;
    instance.receivesShadow = receives;
    scene.meshes.push_back(mesh);
    scene.instances.push_back(instance);
    scene.updateTransforms();
}

Light directional(const glm::vec3& dir) {
    Light light;
    light.type = LightType::Directional;
    light.direction = glm::normalize(dir);
    return light;
}

/// A caster of 10 x 1 x 10 (x and z in [-5, 5]) over a wide ground at y = 0 that casts nothing.
Scene plateScene(const Light& light) {
    Scene scene;
    addBox(scene, {-5, 0.5f, -5}, {5, 1.5f, 5}, true);
    addBox(scene, {-50, 0, -50}, {50, 0, 50}, false);
    scene.lights.push_back(light);
    return scene;
}

/// An orthographic camera looking down at the origin from `tiltDeg` off the vertical (tilted towards
/// +z), framing 20 x 20 world units on its image plane.
glm::mat4 orthoCamera(double tiltDeg) {
    const double a = tiltDeg * kPi / 180.0;
    const glm::vec3 eye(0.0f, float(20.0 * std::cos(a)), float(20.0 * std::sin(a)));
    const glm::vec3 up = tiltDeg == 0.0 ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
    return glm::ortho(-10.0f, 10.0f, -10.0f, 10.0f, 0.1f, 100.0f) * glm::lookAt(eye, glm::vec3(0.0f), up);
}

double tAt(const MapTexels& maps, const glm::dvec3& p, const glm::mat4& camera, size_t light = 0) {
    const std::optional<double> t =
        TexelDensity::texelsPerPixel(maps, light, {p, 1}, {0, 1, 0}, camera, glm::ivec2(kImage));
    EXPECT_TRUE(t.has_value()) << "no map at " << p.x << ", " << p.y << ", " << p.z;
    return t.value_or(0.0);
}

// The fitted map's texel and the orthographic pixel are both constant across the plane: only the
// float matrices' rounding (a few 1e-7 relative) separates t from the closed form.
constexpr double kOrthoTolerance = 1e-5;

} // namespace

TEST(TexelDensityTest, OrthographicMapUnderAnOrthographicCameraStraightDownIsTheRatioOfTheirScales) {
    Scene scene = plateScene(directional({0, -1, 0}));
    FlatLightFits fits;
    fits.setScene(scene, "shadowmap", LightFit{LightFitBounds::Casters, 0.0f}, kMap,
                  FlatLightFits::PointLights::Refuse);
    // The casters' 10 x 10 in x and z, padded by 1e-3 a side (margin 0): 1024 / 10.002 texels per unit;
    // the camera: 256 pixels over 20 units, 12.8 per unit.
    const double expected = (kMap / 10.002) / (kImage / 20.0);
    for (const glm::dvec3 p : {glm::dvec3(0, 0, 0), glm::dvec3(4.5, 0, -3), glm::dvec3(-4.9, 0, 4.9)})
        EXPECT_NEAR(tAt(fits, p, orthoCamera(0.0)), expected, expected * kOrthoTolerance);
    // A pixel's footprint along the tilt is 1 / cos 60 = 2 times longer: sqrt(2) more texels per pixel.
    EXPECT_NEAR(tAt(fits, {1, 0, 1}, orthoCamera(60.0)), expected * std::sqrt(2.0),
                expected * kOrthoTolerance);
    // Outside the map (x beyond the fit) the lighting pass looks nothing up: no value.
    EXPECT_FALSE(fits.texel(0, {{6, 0, 0}, 1}, {6, 0, 0}));
}

TEST(TexelDensityTest, ALightTiltedFromTheReceiversNormalStretchesTexelsByOneOverItsCosine) {
    // The sphere fit frames a square of the casters' bounding sphere, the same from every direction: side
    // 2 (r + 1e-3), r the half-diagonal of the 10 x 1 x 10 box, sqrt(50.25).
    const double side = 2.0 * (std::sqrt(50.25) + 1e-3);
    const double straight = (kMap / side) / (kImage / 20.0);
    for (const double deg : {0.0, 40.0}) {
        const double a = deg * kPi / 180.0;
        Scene scene = plateScene(directional({0.0f, float(-std::cos(a)), float(std::sin(a))}));
        FlatLightFits fits;
        fits.setScene(scene, "shadowmap", LightFit{LightFitBounds::Sphere, 0.0f}, kMap,
                      FlatLightFits::PointLights::Refuse);
        // A unit of ground projects to cos(a) units of the light's plane: cos(a) of the texels per area.
        const double expected = straight * std::sqrt(std::cos(a));
        EXPECT_NEAR(tAt(fits, {0.5, 0, -0.5}, orthoCamera(0.0)), expected, expected * kOrthoTolerance) << deg;
    }
}

TEST(TexelDensityTest, PerspectiveCameraStraightDownSeesEveryPointOfAParallelPlaneAtOnePixelSize) {
    Scene scene = plateScene(directional({0, -1, 0}));
    FlatLightFits fits;
    fits.setScene(scene, "shadowmap", LightFit{LightFitBounds::Casters, 0.0f}, kMap,
                  FlatLightFits::PointLights::Refuse);
    const double h = 10.0, fov = 60.0 * kPi / 180.0;
    const glm::mat4 camera =
        glm::perspective(float(fov), 1.0f, 0.1f, 100.0f) *
        glm::lookAt(glm::vec3(0.0f, float(h), 0.0f), glm::vec3(0.0f), glm::vec3(0, 0, -1));
    const double pixel = 2.0 * h * std::tan(fov / 2.0) / kImage; // world units per pixel on the plane
    const double expected = (kMap / 10.002) * pixel;
    // A perspective map of the plane is affine: the finite differences are exact up to rounding.
    for (const glm::dvec3 p : {glm::dvec3(0, 0, 0), glm::dvec3(3, 0, -2), glm::dvec3(-4.5, 0, -4.5)})
        EXPECT_NEAR(tAt(fits, p, camera), expected, expected * kOrthoTolerance);
}

namespace {
/// A point light 5 above the ground's origin with a caster beside it (so that its map is drawn).
Scene pointLightScene() {
    Scene scene;
    addBox(scene, {2, 1, 2}, {3, 2, 3}, true);
    addBox(scene, {-50, 0, -50}, {50, 0, 50}, false);
    Light light;
    light.type = LightType::Point;
    light.position = {0, 5, 0};
    scene.lights.push_back(light);
    return scene;
}
// The cube face's map is affine on a parallel plane (exact up to rounding); the paraboloid's is not, and
// its central differences over a quarter of a pixel's footprint (0.02 units, 5 from the light) are off
// by about (0.02 / 5)^2 = 2e-5 relative.
constexpr double kParaboloidTolerance = 2e-4;
} // namespace

TEST(TexelDensityTest, CubeFaceBelowAPointLightHasResolutionOverTwiceTheHeightTexelsPerUnit) {
    Scene scene = pointLightScene();
    OmniLightSet lights;
    lights.setScene(scene, OmniShape::Cube, kMap);
    const double expected = (kMap / (2.0 * 5.0)) / (kImage / 20.0);
    for (const glm::dvec3 p : {glm::dvec3(0, 0, 0), glm::dvec3(3, 0, -2), glm::dvec3(-4, 0, 4)}) {
        EXPECT_NEAR(tAt(lights, p, orthoCamera(0.0)), expected, expected * kOrthoTolerance);
        EXPECT_EQ(lights.texel(0, {p, 1}, p)->map, 3); // -Y, GL's face order
    }
}

TEST(TexelDensityTest, ParaboloidHalfFollowsItsNonlinearProjection) {
    Scene scene = pointLightScene();
    OmniLightSet lights;
    lights.setScene(scene, OmniShape::Paraboloid, kMap);
    const double h = 5.0, pixelsPerUnit = kImage / 20.0;
    // Straight below the light, map radius tan(alpha / 2) ~ rho / 2h, a map unit res / 2 texels: res / 4h
    // texels per world unit in both directions.
    EXPECT_NEAR(tAt(lights, {0, 0, 0}, orthoCamera(0.0)), kMap / (4.0 * h) / pixelsPerUnit,
                kMap / (4.0 * h) / pixelsPerUnit * kParaboloidTolerance);
    // At rho from the axis, alpha = atan(rho / h): radially d tan(alpha / 2) / d rho = sec^2(alpha / 2) / 2 *
    // cos^2(alpha) / h, tangentially tan(alpha / 2) / rho.
    for (const glm::dvec3 p : {glm::dvec3(3, 0, 0), glm::dvec3(1.2, 0, -1.6), glm::dvec3(-6, 0, 8)}) {
        const double rho = std::hypot(p.x, p.z), alpha = std::atan(rho / h);
        const double radial = 0.5 / std::pow(std::cos(alpha / 2.0), 2.0) * std::pow(std::cos(alpha), 2.0) / h;
        const double tangential = std::tan(alpha / 2.0) / rho;
        const double expected = 0.5 * kMap * std::sqrt(radial * tangential) / pixelsPerUnit;
        EXPECT_NEAR(tAt(lights, p, orthoCamera(0.0)), expected, expected * kParaboloidTolerance) << rho;
        EXPECT_EQ(lights.texel(0, {p, 1}, p)->map, 0); // below the light: the front half
    }
    EXPECT_EQ(lights.texel(0, {{1, 7, 0}, 1}, {1, 7, 0})->map, 1); // above it: the back half
}

TEST(TexelDensityTest, CascadedReadsTheCascadeWhoseSplitsHoldTheViewDepth) {
    Scene scene;
    addBox(scene, {-40, 0, -80}, {40, 0, 0}, false);                  // the ground: receives, casts nothing
    addBox(scene, {-1000, -2, -1000}, {1000, 21, 1000}, true, false); // casters wider than any slice
    scene.lights.push_back(directional({0, -1, 0}));
    CascadedMaps maps;
    maps.setScene(scene, 3);
    PropertySet p("cascaded", Cascaded::declaration().properties);
    p.apply({{Cascaded::kCascades, "3"}, {Cascaded::kStabilize, "false"}, {Cascaded::kBlend, "0"}});
    const glm::vec3 eye(0, 10, 0);
    const double fov = 60.0 * kPi / 180.0;
    const glm::mat4 view = glm::lookAt(eye, glm::vec3(0, 0, -20), glm::vec3(0, 1, 0));
    const glm::mat4 proj = glm::perspective(float(fov), 1.0f, 0.1f, 100.0f);
    maps.fit(view, proj, p, kMap);
    const std::vector<float>& splits = maps.splits();
    ASSERT_EQ(splits.size(), 4u);

    const glm::dmat4 toWorld = glm::inverse(glm::dmat4(view));
    const glm::dvec3 forward = glm::normalize(glm::dvec3(0, -10, -20));
    const double tanHalf = std::tan(fov / 2.0), focal = 0.5 * kImage / tanHalf;
    int seen = 0;
    for (int c = 0; c < 3; ++c) {
        // The slice's 8 corners in the world; the tight box (light straight down: world x and z) bounds them.
        glm::dvec2 lo(1e30), hi(-1e30);
        for (const double d : {double(splits[size_t(c)]), double(splits[size_t(c) + 1])})
            for (int k = 0; k < 4; ++k) {
                const glm::dvec3 v((k & 1 ? 1 : -1) * d * tanHalf, (k & 2 ? 1 : -1) * d * tanHalf, -d);
                const glm::dvec3 w = glm::dvec3(toWorld * glm::dvec4(v, 1.0));
                lo = glm::min(lo, glm::dvec2(w.x, w.z));
                hi = glm::max(hi, glm::dvec2(w.x, w.z));
            }
        const double texelsPerArea = double(kMap) * kMap / ((hi.x - lo.x) * (hi.y - lo.y));
        // A ground point on the view's vertical plane at 70% of the slice's depth interval.
        const double depth = splits[size_t(c)] + 0.7 * (splits[size_t(c) + 1] - splits[size_t(c)]);
        const double z =
            (depth * std::sqrt(500.0) - 100.0) / 20.0; // depth of (0, 0, -z): (100 + 20 z) / sqrt 500
        const glm::dvec3 q(0.0, 0.0, -z);
        const glm::dvec4 clip = glm::dmat4(proj * view) * glm::dvec4(q, 1.0);
        if (!(std::abs(clip.y / clip.w) < 1.0) || z <= 0.0) continue; // not in view: no sample there
        ++seen;
        const glm::dvec3 ray = q - glm::dvec3(eye);
        const double r = glm::length(ray);
        const double cosAlpha = glm::dot(ray / r, forward), cosBeta = std::abs(ray.y) / r;
        const double pixelsPerArea = focal * focal * cosBeta / (r * r * std::pow(cosAlpha, 3.0));
        const double expected = std::sqrt(texelsPerArea / pixelsPerArea);
        const std::optional<MapPoint> at = maps.texel(0, {q, 0}, q);
        ASSERT_TRUE(at.has_value()) << "cascade " << c;
        EXPECT_EQ(at->map, c);
        // Orthographic map, perspective camera (exact closed form): the float matrices' rounding.
        const double t =
            TexelDensity::texelsPerPixel(maps, 0, {q, 0}, {0, 1, 0}, proj * view, glm::ivec2(kImage))
                .value_or(0.0);
        EXPECT_NEAR(t, expected, expected * kOrthoTolerance) << "cascade " << c;
    }
    EXPECT_GE(seen, 2); // the cascades' texel sizes differ: a wrong cascade would miss by their ratio
}

TEST(TexelDensityTest, SummaryIsTheMedianFifthPercentileAndMinimum) {
    std::vector<double> v;
    for (int i = 100; i >= 0; --i) v.push_back(double(i)); // 0 .. 100
    const TexelDensity::Summary s = TexelDensity::summarize(v);
    EXPECT_EQ(s.samples, 101u);
    EXPECT_DOUBLE_EQ(s.p50, 50.0);
    EXPECT_DOUBLE_EQ(s.p5, 5.0);
    EXPECT_DOUBLE_EQ(s.min, 0.0);
    EXPECT_EQ(TexelDensity::summarize({}).samples, 0u);
}

// Every form of every technique the matrix holds to the map rule (bench/golden/AccuracyBounds.cpp's
// table: the shadow-map family) answers where its lighting pass looks a point up, so that no member's
// columns are silently empty; a technique without a map (`volume`) answers nothing. Objects only, no
// context.
TEST(TexelDensityTest, EveryFormOfAMapRuleTechniqueReportsItsTexels) {
    size_t checked = 0;
    for (const std::string& name : TechniqueRegistry::names()) {
        MatrixCell cell;
        cell.technique = name;
        cell.lights = {CellAccuracy{}};
        const bool mapRule = AccuracyBounds::derive(cell, 0).rule == "map";
        for (Api api : {Api::GL, Api::Vulkan}) {
            if (!TechniqueRegistry::has(name, api)) continue;
            const std::unique_ptr<Technique> t = TechniqueRegistry::create(TechniqueSpec::parse(name), api);
            EXPECT_EQ(t->mapTexels() != nullptr, mapRule) << name << " on " << apiName(api);
            checked += mapRule;
        }
    }
    EXPECT_GE(checked, 18u); // nine map-rule members on both APIs
}
