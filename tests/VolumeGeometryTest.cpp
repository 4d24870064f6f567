// Unit tests of techniques/volume/VolumeGeometry (GPU Gems ch. 9, sections 9.2.3, 9.5.2-9.5.4, 9.6.2-9.6.3):
// every expectation is a value worked out by hand for a camera at the origin looking down -z with a
// 90 degree field of view (so x_ndc = x / -z and y_ndc = y / -z), or a closed form.
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "techniques/volume/VolumeGeometry.h"

using namespace sb;

namespace {

// Float matrix products of values ~1-10: 1e-5 is a few ulps.
constexpr float kTol = 1e-5f;
constexpr float kEps = 1e-6f; // infinitePerspective's default guard
const float kFov90 = glm::radians(90.0f);

/// The test camera: eye at `eye` looking down -z, 90 degrees, square, near 1, far at infinity.
glm::mat4 viewProjAt(const glm::vec3& eye) {
    return VolumeGeometry::infinitePerspective(kFov90, 1.0f, 1.0f) *
           glm::lookAt(eye, eye + glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
}

Aabb box(const glm::vec3& centre, float half) {
    return {centre - glm::vec3(half), centre + glm::vec3(half)};
}

void expectPlaneNear(const Plane& got, const Plane& expected, const char* what) {
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(got[i], expected[i], kTol) << what << " component " << i;
}

Light pointLight(const glm::vec3& position, float range) {
    Light l;
    l.type = LightType::Point;
    l.position = position;
    l.range = range;
    return l;
}

} // namespace

TEST(VolumeGeometryTest, InfinitePerspectiveMapsNearToMinusOneAndInfinityInsideFarClip) {
    const float nearZ = 0.25f, aspect = 1.5f, fov = glm::radians(60.0f);
    const glm::mat4 p = VolumeGeometry::infinitePerspective(fov, aspect, nearZ);
    // Any point on the near plane: z_ndc = (-(eps - 1) n + (eps - 2) n) / n = -1 exactly in reals;
    // 1e-6 allows the float rounding of (eps - 1) and (eps - 2) n.
    for (const glm::vec2 xy : {glm::vec2(0.0f), glm::vec2(0.1f, -0.07f), glm::vec2(-0.2f, 0.13f)}) {
        const glm::vec4 c = p * glm::vec4(xy, -nearZ, 1.0f);
        EXPECT_NEAR(c.z / c.w, -1.0f, 1e-6f);
    }
    // The point at infinity straight ahead: z = 1 - eps, w = 1 (both exact products of 1).
    const glm::vec4 inf = p * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f);
    EXPECT_FLOAT_EQ(inf.w, 1.0f);
    EXPECT_FLOAT_EQ(inf.z / inf.w, 1.0f - kEps);
    EXPECT_LT(inf.z / inf.w, 1.0f);
    // glm::perspective with far = 1e9 differs from the limit by ~n / f and by the guard's eps * n:
    // both below 1e-5.
    const glm::mat4 far = glm::perspective(fov, aspect, nearZ, 1e9f);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(p[c][r], far[c][r], kTol) << "column " << c << " row " << r;
    // The x and y scales by hand: cot(30 degrees) = sqrt(3).
    EXPECT_NEAR(p[1][1], std::sqrt(3.0f), kTol);
    EXPECT_NEAR(p[0][0], std::sqrt(3.0f) / aspect, kTol);
}

TEST(VolumeGeometryTest, FrustumPlanesOfAKnownCamera) {
    // Eye at (1, 2, 3) looking down -z with 90 degrees: the side planes are at 45 degrees through the
    // eye, e.g. left: x - 1 >= (z - 3) (view z negative in front), normal (1, 0, -1) / sqrt 2,
    // d = -n.eye; near: z <= 3 - 1, normal (0, 0, -1), d = 2.
    const glm::vec3 eye(1.0f, 2.0f, 3.0f);
    const auto planes = VolumeGeometry::frustumPlanes(viewProjAt(eye));
    const float s = 1.0f / std::sqrt(2.0f);
    auto through = [&](const glm::vec3& n) { return Plane(n, -glm::dot(n, eye)); };
    expectPlaneNear(planes[0], through({s, 0, -s}), "left");
    expectPlaneNear(planes[1], through({-s, 0, -s}), "right");
    expectPlaneNear(planes[2], through({0, s, -s}), "bottom");
    expectPlaneNear(planes[3], through({0, -s, -s}), "top");
    expectPlaneNear(planes[4], Plane(0, 0, -1, 2), "near");
    // A point 5 ahead is inside all of them, at the distance of a 45-degree plane: 5 / sqrt 2.
    const glm::vec4 ahead(eye + glm::vec3(0, 0, -5), 1.0f);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(glm::dot(planes[size_t(i)], ahead), 5.0f * s, kTol);
    EXPECT_NEAR(glm::dot(planes[4], ahead), 4.0f, kTol);
}

TEST(VolumeGeometryTest, OutsideAnyNeedsAllPointsOutsideOnePlane) {
    const auto planes = VolumeGeometry::frustumPlanes(viewProjAt(glm::vec3(0.0f)));
    const glm::vec4 behind[2] = {{0, 0, 1, 1}, {3, -2, 5, 1}};       // both behind the near plane
    const glm::vec4 split[2] = {{-10, 0, -5, 1}, {10, 0, -5, 1}};    // left of left, right of right
    const glm::vec4 ahead[2] = {{0, 0, -1, 0}, {0.5f, 0.5f, -1, 0}}; // directions into the view
    EXPECT_TRUE(VolumeGeometry::outsideAny(planes, behind, 2));
    EXPECT_FALSE(VolumeGeometry::outsideAny(planes, split, 2)); // no single plane separates them
    EXPECT_FALSE(VolumeGeometry::outsideAny(planes, ahead, 2));
    const glm::vec4 backwards[1] = {{0, 0, 1, 0}}; // the direction behind the camera
    EXPECT_TRUE(VolumeGeometry::outsideAny(planes, backwards, 1));
}

TEST(VolumeGeometryTest, CornersAndCornersAtInfinity) {
    const Aabb b{{1, 2, 3}, {4, 5, 6}};
    const auto c = VolumeGeometry::corners(b);
    EXPECT_EQ(c[0], glm::vec4(1, 2, 3, 1));
    EXPECT_EQ(c[7], glm::vec4(4, 5, 6, 1));
    EXPECT_EQ(c[5], glm::vec4(4, 2, 6, 1)); // bit 0: x, bit 1: y, bit 2: z
    // Point light at (1, 1, 1): corner - light, w = 0.
    const auto p = VolumeGeometry::cornersAtInfinity(b, {1, 1, 1, 1});
    EXPECT_EQ(p[0], glm::vec4(0, 1, 2, 0));
    EXPECT_EQ(p[7], glm::vec4(3, 4, 5, 0));
    // Directional light towards (0, 1, 0): every corner goes to the one point (0, -1, 0, 0).
    for (const glm::vec4& q : VolumeGeometry::cornersAtInfinity(b, {0, 1, 0, 0}))
        EXPECT_EQ(q, glm::vec4(0, -1, 0, 0));
}

TEST(VolumeGeometryTest, CullVolumeCullsCapsAndSidesSeparately) {
    const auto frustum = VolumeGeometry::frustumPlanes(viewProjAt(glm::vec3(0.0f)));
    // In view, light just above: caster and sides visible, but the dark cap is at infinity straight
    // down (directions (+-0.5, -9.5 +- 0.5, +-0.5)), outside the bottom plane (45 degrees).
    auto c = VolumeGeometry::cullVolume(frustum, box({0, 0, -5}, 0.5f), {0, 10, -5, 1});
    EXPECT_FALSE(c.lightCap);
    EXPECT_TRUE(c.darkCap);
    EXPECT_FALSE(c.sides);
    // Caster behind the camera, light further behind: the caster (light cap) is culled but its shadow
    // reaches into the view towards -z (dark cap at infinity ahead, sides crossing the frustum).
    c = VolumeGeometry::cullVolume(frustum, box({0, 0, 5}, 0.5f), {0, 0, 10, 1});
    EXPECT_TRUE(c.lightCap);
    EXPECT_FALSE(c.darkCap);
    EXPECT_FALSE(c.sides);
    // Caster behind the camera, light in front: the whole volume goes away behind: all culled.
    c = VolumeGeometry::cullVolume(frustum, box({0, 0, 5}, 0.5f), {0, 0, -10, 1});
    EXPECT_TRUE(c.lightCap && c.darkCap && c.sides);
    // Caster in view with the light behind the camera: the dark cap is at infinity ahead, visible.
    c = VolumeGeometry::cullVolume(frustum, box({0, 0, -5}, 0.5f), {0, 0, 10, 1});
    EXPECT_FALSE(c.lightCap || c.darkCap || c.sides);
    // Caster in view, light straight ahead beyond it: the shadow comes back towards and behind the
    // camera: dark cap at infinity behind (culled), light cap and sides visible.
    c = VolumeGeometry::cullVolume(frustum, box({0, 0, -5}, 0.5f), {0, 0, -20, 1});
    EXPECT_FALSE(c.lightCap);
    EXPECT_TRUE(c.darkCap);
    EXPECT_FALSE(c.sides);
    // Directional light: caster far to the right (x = 50 at z = -5 is past the right plane x <= 5),
    // shadow going further right and down (L towards (-1, 1, 0)): all outside the right plane.
    c = VolumeGeometry::cullVolume(frustum, box({50, 0, -5}, 0.5f), {-1, 1, 0, 0});
    EXPECT_TRUE(c.lightCap && c.darkCap && c.sides);
    // The same caster with the sun towards (1, 0, 0.1): the shadow sweeps across the view to -x. The
    // caster is outside the right plane, the dark cap (the one point (-1, 0, -0.1) at infinity, 84
    // degrees off the axis) outside the left plane: only the sides may be seen.
    c = VolumeGeometry::cullVolume(frustum, box({50, 0, -5}, 0.5f), {1, 0, 0.1f, 0});
    EXPECT_TRUE(c.lightCap);
    EXPECT_TRUE(c.darkCap);
    EXPECT_FALSE(c.sides);
}

TEST(VolumeGeometryTest, NearRectangleIsTheInverseOfTheNdcCorners) {
    // Eye at (1, 2, 3), near 1, 90 degrees: the rectangle is eye + (+-1, +-1, -1), counter-clockwise
    // from bottom-left seen from the eye.
    const auto r = VolumeGeometry::nearRectangle(viewProjAt({1, 2, 3}));
    const glm::vec3 expected[4] = {{0, 1, 2}, {2, 1, 2}, {2, 3, 2}, {0, 3, 2}};
    for (size_t i = 0; i < 4; ++i)
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(r[i][k], expected[i][k], kTol) << "corner " << i;
}

TEST(VolumeGeometryTest, OcclusionPyramidOfAPointLight) {
    // Near rectangle (+-1, +-1, -1); light at (0, 0, -10): the pyramid's half-width at z is
    // (10 + z) / 9, 0.56 at z = -5.
    const auto rect = VolumeGeometry::nearRectangle(viewProjAt(glm::vec3(0.0f)));
    const glm::vec4 light(0, 0, -10, 1);
    EXPECT_TRUE(VolumeGeometry::mayShadowViewport(rect, light, box({0, 0, -5}, 0.5f))); // on the axis
    EXPECT_TRUE(
        VolumeGeometry::mayShadowViewport(rect, light, box({0.9f, 0, -5}, 0.5f)));        // overlaps the side
    EXPECT_FALSE(VolumeGeometry::mayShadowViewport(rect, light, box({5, 0, -5}, 0.5f)));  // beside it
    EXPECT_FALSE(VolumeGeometry::mayShadowViewport(rect, light, box({0, 0, -15}, 0.3f))); // beyond the light
    EXPECT_FALSE(VolumeGeometry::mayShadowViewport(rect, light, box({0, 0, 2}, 0.5f)));   // behind the camera
    // The light behind the camera: the pyramid reaches back from the near plane to it.
    EXPECT_TRUE(VolumeGeometry::mayShadowViewport(rect, {0, 0, 5, 1}, box({0, 0, 0}, 0.3f)));
    EXPECT_FALSE(VolumeGeometry::mayShadowViewport(rect, {0, 0, 5, 1}, box({0, 0, -5}, 0.5f)));
    // Homogeneous light with w = 2: the same point (0, 0, -10).
    EXPECT_FALSE(VolumeGeometry::mayShadowViewport(rect, {0, 0, -20, 2}, box({5, 0, -5}, 0.5f)));
    // Light in the near plane: a flat pyramid, no decision: conservative true.
    EXPECT_TRUE(VolumeGeometry::mayShadowViewport(rect, {5, 0, -1, 1}, box({50, 50, -50}, 0.5f)));
}

TEST(VolumeGeometryTest, OcclusionPyramidOfADirectionalLight) {
    // L points towards the light: (0, 0, -1) puts the sun straight ahead, and the occlusion region is
    // the near rectangle swept along -z: |x|, |y| <= 1, z <= -1.
    const auto rect = VolumeGeometry::nearRectangle(viewProjAt(glm::vec3(0.0f)));
    const glm::vec4 ahead(0, 0, -1, 0);
    EXPECT_TRUE(VolumeGeometry::mayShadowViewport(rect, ahead, box({0, 0, -50}, 0.5f)));
    EXPECT_TRUE(VolumeGeometry::mayShadowViewport(rect, ahead, box({1.3f, 0, -50}, 0.5f)));
    EXPECT_FALSE(VolumeGeometry::mayShadowViewport(rect, ahead, box({1.6f, 0, -50}, 0.5f)));
    EXPECT_FALSE(VolumeGeometry::mayShadowViewport(rect, ahead, box({0, 0, 3}, 0.5f)));
    // Sun behind the camera (L = +z): the region is the rectangle swept backwards.
    EXPECT_TRUE(VolumeGeometry::mayShadowViewport(rect, {0, 0, 1, 0}, box({0, 0, 3}, 0.5f)));
    EXPECT_FALSE(VolumeGeometry::mayShadowViewport(rect, {0, 0, 1, 0}, box({0, 0, -50}, 0.5f)));
    // Oblique sun towards (1, 0, -1): at z = -11 the swept rectangle spans x in [9, 11].
    EXPECT_TRUE(VolumeGeometry::mayShadowViewport(rect, {1, 0, -1, 0}, box({10, 0, -11}, 0.5f)));
    EXPECT_FALSE(VolumeGeometry::mayShadowViewport(rect, {1, 0, -1, 0}, box({0, 0, -11}, 0.5f)));
    // Sun parallel to the near plane: no pyramid, conservative true.
    EXPECT_TRUE(VolumeGeometry::mayShadowViewport(rect, {1, 0, 0, 0}, box({0, 40, 40}, 0.5f)));
}

TEST(VolumeGeometryTest, LightReachesByRangeAndSpotCone) {
    Light sun;
    EXPECT_TRUE(VolumeGeometry::lightReaches(sun, box({1000, 0, 0}, 1)));
    EXPECT_TRUE(VolumeGeometry::lightReaches(pointLight({0, 0, 0}, 0.0f), box({1000, 0, 0}, 1))); // no range
    const Light point = pointLight({0, 0, 0}, 5.0f);
    // Box [3, 4]^3: closest point (3, 3, 3) at sqrt(27) = 5.196 > 5.
    EXPECT_FALSE(VolumeGeometry::lightReaches(point, {{3, 3, 3}, {4, 4, 4}}));
    // Box [4.9, 6] x [-1, 1]^2: closest (4.9, 0, 0) at 4.9 < 5 although all its corners are farther.
    EXPECT_TRUE(VolumeGeometry::lightReaches(point, {{4.9f, -1, -1}, {6, 1, 1}}));
    EXPECT_TRUE(VolumeGeometry::lightReaches(point, box({0, 0, 0}, 0.5f))); // contains the light

    Light spot = pointLight({0, 0, 0}, 100.0f);
    spot.type = LightType::Spot;
    spot.direction = {0, -1, 0};
    spot.spotOuterDeg = 30.0f;
    EXPECT_TRUE(VolumeGeometry::lightReaches(spot, box({0, -10, 0}, 0.5f))); // on the axis
    // Centre at 45 degrees off the axis, d = 14.14: radius 0.866 subtends 3.5 degrees: 41.5 > 30.
    EXPECT_FALSE(VolumeGeometry::lightReaches(spot, box({10, -10, 0}, 0.5f)));
    // Half extent 6: radius 10.39 subtends 47.3 degrees: 45 - 47.3 < 30, may reach.
    EXPECT_TRUE(VolumeGeometry::lightReaches(spot, box({10, -10, 0}, 6.0f)));
    // Centre at 25 degrees (tan 25 = 0.466): inside the cone.
    EXPECT_TRUE(VolumeGeometry::lightReaches(spot, box({4.66f, -10, 0}, 0.1f)));
    EXPECT_FALSE(VolumeGeometry::lightReaches(spot, box({0, 10, 0}, 0.5f)));  // behind the spot
    EXPECT_TRUE(VolumeGeometry::lightReaches(spot, box({0, 0.2f, 0}, 0.5f))); // contains the apex
    spot.range = 5.0f;
    EXPECT_FALSE(VolumeGeometry::lightReaches(spot, box({0, -10, 0}, 0.5f))); // in the cone, out of range
}

TEST(VolumeGeometryTest, ScissorRectOfTheRangeCube) {
    const glm::mat4 vp = viewProjAt(glm::vec3(0.0f));
    // No range: the whole viewport.
    EXPECT_EQ(VolumeGeometry::scissorRect(pointLight({0, 0, -10}, 0.0f), vp, 100, 80),
              glm::ivec4(0, 0, 100, 80));
    // Cube [-1, 1]^2 x [-11, -9]: widest at z = -9, ndc +-1/9, pixels 50 -+ 5.56 -> [44, 56).
    EXPECT_EQ(VolumeGeometry::scissorRect(pointLight({0, 0, -10}, 1.0f), vp, 100, 100),
              glm::ivec4(44, 44, 12, 12));
    // Off to the right (x in [49, 51] at z >= -11: ndc x >= 4.45) and behind the camera: nothing.
    EXPECT_FALSE(VolumeGeometry::scissorRect(pointLight({50, 0, -10}, 1.0f), vp, 100, 100));
    EXPECT_FALSE(VolumeGeometry::scissorRect(pointLight({0, 0, 10}, 1.0f), vp, 100, 100));
    // Straddling the near plane (z = -1): cube x in [-0.5, 1.5], y in [-1, 1], z in [-2.5, -0.5],
    // kept for z in [-2.5, -1]. The kept extremes are at z = -1: ndc x in [-0.5, 1.5], y in [-1, 1].
    // On 90 x 90 pixels x starts at 0.25 * 90 = 22.5 -> 22. Without the near clip the corners at
    // z = -0.5 would reach ndc -1 (pixel 0).
    EXPECT_EQ(VolumeGeometry::scissorRect(pointLight({0.5f, 0, -1.5f}, 1.0f), vp, 90, 90),
              glm::ivec4(22, 0, 68, 90));
    // Surrounding the camera: the full viewport.
    EXPECT_EQ(VolumeGeometry::scissorRect(pointLight({0, 0, 0}, 2.0f), vp, 64, 48), glm::ivec4(0, 0, 64, 48));
}

TEST(VolumeGeometryTest, DepthBoundsOfTheRangeCube) {
    // The infinite projection's window depth at view distance t: (1 - eps / 2) (1 - n / t), from
    // z_ndc = (1 - eps) - (2 - eps) n / t. 1e-6: float rounding of values < 1.
    const glm::mat4 view(1.0f);
    const glm::mat4 proj = VolumeGeometry::infinitePerspective(kFov90, 1.0f, 1.0f);
    auto depth = [](float t) { return (1.0f - 0.5f * kEps) * (1.0f - 1.0f / t); };
    EXPECT_FALSE(VolumeGeometry::depthBounds(pointLight({0, 0, -10}, 0.0f), view, proj));
    auto b = VolumeGeometry::depthBounds(pointLight({0, 0, -10}, 1.0f), view, proj);
    ASSERT_TRUE(b);
    EXPECT_NEAR(b->x, depth(9.0f), 1e-6f);
    EXPECT_NEAR(b->y, depth(11.0f), 1e-6f);
    // Reaching behind the near plane: from 0 to the far face at distance 3.
    b = VolumeGeometry::depthBounds(pointLight({0.3f, 0, -1}, 2.0f), view, proj);
    ASSERT_TRUE(b);
    EXPECT_EQ(b->x, 0.0f);
    EXPECT_NEAR(b->y, depth(3.0f), 1e-6f);
    // A finite glm::perspective (n = 1, f = 100) and a view that moves the eye to z = 5: window depth
    // f (t - n) / ((f - n) t) at t = 5 + 10 -+ 2.
    const glm::mat4 finite = glm::perspective(kFov90, 1.0f, 1.0f, 100.0f);
    const glm::mat4 moved = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -5));
    b = VolumeGeometry::depthBounds(pointLight({0, 0, -10}, 2.0f), moved, finite);
    ASSERT_TRUE(b);
    auto finiteDepth = [](float t) { return 100.0f * (t - 1.0f) / (99.0f * t); };
    EXPECT_NEAR(b->x, finiteDepth(13.0f), 1e-6f);
    EXPECT_NEAR(b->y, finiteDepth(17.0f), 1e-6f);
}

TEST(VolumeGeometryTest, BoundedExtrusionReachesPastTheSceneAlongTheLight) {
    // Hand-computed: scene [-10, 10] x [0, 5] x [-10, 10], caster [-1, 1] x [2, 3] x [-1, 1].
    Aabb scene, caster;
    scene.extend(glm::vec3(-10, 0, -10));
    scene.extend(glm::vec3(10, 5, 10));
    caster.extend(glm::vec3(-1, 2, -1));
    caster.extend(glm::vec3(1, 3, 1));
    const float pad = 1e-4f * glm::length(scene.extent());
    // Straight down: the caster's top must reach the ground, 3 below it.
    EXPECT_NEAR(VolumeGeometry::boundedExtrusion(scene, caster, {0, -1, 0}, 0.0f), 3.0f + pad, 1e-5f);
    EXPECT_NEAR(VolumeGeometry::boundedExtrusion(scene, caster, {0, -1, 0}), 3.0f * 1.01f + pad, 1e-5f);
    // 45 degrees in x: the ground (3 / sin 45) comes before the x = 10 wall (11 / cos 45).
    const glm::vec3 slant = glm::normalize(glm::vec3(1, -1, 0));
    EXPECT_NEAR(VolumeGeometry::boundedExtrusion(scene, caster, slant, 0.0f), 3.0f * std::sqrt(2.0f) + pad,
                1e-5f);
    // Nearly horizontal: the wall, 11 from the caster's far-back face, comes first.
    const glm::vec3 flat = glm::normalize(glm::vec3(1, -0.01f, 0));
    EXPECT_NEAR(VolumeGeometry::boundedExtrusion(scene, caster, flat, 0.0f), 11.0f / flat.x + pad, 1e-4f);
    EXPECT_EQ(VolumeGeometry::boundedExtrusion(scene, caster, {0, 0, 0}), 0.0f);
}

TEST(VolumeGeometryTest, BoundedExtrusionCoversEveryPointOfTheInfiniteVolumeInsideTheScene) {
    // The property the bound is for, checked by sampling: X in the caster's box, P = X + t dir with P
    // still in the scene box must have t <= D (else the truncated volume would miss P's shadow).
    Aabb scene, caster;
    scene.extend(glm::vec3(-20, 0, -15));
    scene.extend(glm::vec3(25, 8, 15));
    caster.extend(glm::vec3(-2, 3, 1));
    caster.extend(glm::vec3(1, 6, 4));
    uint32_t state = 12345u;
    auto uniform = [&]() {
        state = state * 1664525u + 1013904223u; // LCG: reproducible, no <random> distribution drift
        return float(state >> 8) / float(1u << 24);
    };
    for (int d = 0; d < 50; ++d) {
        const glm::vec3 dir =
            glm::normalize(glm::vec3(uniform() * 2 - 1, -0.05f - uniform(), uniform() * 2 - 1));
        const float bound = VolumeGeometry::boundedExtrusion(scene, caster, dir, 0.0f);
        float longest = 0.0f;
        for (int s = 0; s < 200; ++s) {
            const glm::vec3 x = caster.min + glm::vec3(uniform(), uniform(), uniform()) * caster.extent();
            float exit = std::numeric_limits<float>::max(); // ray-box exit, slab by slab
            for (int i = 0; i < 3; ++i)
                if (dir[i] != 0.0f)
                    exit = std::min(exit, ((dir[i] > 0 ? scene.max[i] : scene.min[i]) - x[i]) / dir[i]);
            longest = std::max(longest, exit);
        }
        EXPECT_LE(longest, bound * (1.0f + 1e-6f)) << "direction " << d;
        // And not wastefully long: within 2x of the longest sampled need (the bound is a max of
        // per-slab maxima, tight when one slab is the exit everywhere).
        EXPECT_LE(bound, 2.0f * longest + 1e-3f) << "direction " << d;
    }
}
