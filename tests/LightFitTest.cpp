// The light cameras of scenes/LightFit (shadowmap's depth maps, projective's directional projector)
// against the clip coordinates worked out by hand from the fit's definition: x and y framing the
// casters with 1% + 1e-3 of padding, depth covering every instance with 1e-3 of the scene's radius,
// and the spot's frustum between the scene's nearest and farthest points along the light's axis.
#include <cmath>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "scenes/LightFit.h"

using namespace sb;

namespace {

// Clip coordinates of values ~1 from products of floats of magnitude ~100: a few ulps of the inputs.
constexpr float kTol = 1e-4f;

std::vector<glm::vec3> corners(const glm::vec3& lo, const glm::vec3& hi) {
    std::vector<glm::vec3> out;
    for (int i = 0; i < 8; ++i)
        out.emplace_back(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
    return out;
}

/// Adds a box [lo, hi] as a mesh of its 8 corners (bounds are all the fit reads) and one instance.
void addBox(Scene& scene, const glm::vec3& lo, const glm::vec3& hi, bool casts) {
    Mesh mesh;
    mesh.name = "box" + std::to_string(scene.meshes.size());
    mesh.positions = corners(lo, hi);
    mesh.normals.assign(8, glm::vec3(0, 1, 0));
    Instance instance;
    instance.mesh = uint32_t(scene.meshes.size());
    instance.castsShadow = casts;
    scene.meshes.push_back(mesh);
    scene.instances.push_back(instance);
    scene.updateTransforms();
}

glm::vec3 clip(const glm::mat4& m, const glm::vec3& p) {
    const glm::vec4 c = m * glm::vec4(p, 1.0f);
    EXPECT_GT(c.w, 0.0f);
    return glm::vec3(c) / c.w;
}

Light directional(const glm::vec3& dir) {
    Light light;
    light.type = LightType::Directional;
    light.direction = glm::normalize(dir);
    return light;
}

} // namespace

TEST(LightFitTest, DirectionalFramesTheCastersWithTheirPaddingAndEveryReceiverInDepth) {
    Scene scene;
    addBox(scene, {-30, 0, -20}, {40, 12, 25}, true);       // the caster
    addBox(scene, {-100, -5, -100}, {100, -5, 100}, false); // a ground below it, wider than the map
    const glm::mat4 m = fitLightViewProjection(scene, directional({0, -1, 0}));
    // Straight down the light camera's up is +z (anyPerpendicularUp), so x_view = -(x - 5) and
    // y_view = z - 2.5 around the casters' centre (5, 6, 2.5). Half extents 35 and 22.5, padded by
    // 1% of the full extent + 1e-3 each side: the casters' extreme corners land at 35 / 35.701 and
    // 22.5 / 22.951 of the map's half width.
    const float ex = 35.0f / (35.0f + 0.701f), ey = 22.5f / (22.5f + 0.451f);
    EXPECT_NEAR(clip(m, {-30, 12, -20}).x, ex, kTol);
    EXPECT_NEAR(clip(m, {40, 12, -20}).x, -ex, kTol);
    EXPECT_NEAR(clip(m, {40, 12, 25}).y, ey, kTol);
    EXPECT_NEAR(clip(m, {40, 0, -20}).y, -ey, kTol);
    // Depth: the scene spans y in [-5, 12]; its radius is half the diagonal of (200, 17, 200). The
    // range is padded by 1e-3 radius at both ends, and depth grows downwards, along the light.
    const float r = 0.5f * std::sqrt(200.0f * 200.0f + 17.0f * 17.0f + 200.0f * 200.0f);
    const float span = 17.0f + 2e-3f * r;
    EXPECT_NEAR(clip(m, {0, 12, 0}).z, -1.0f + 2.0f * 1e-3f * r / span, kTol);
    EXPECT_NEAR(clip(m, {0, -5, 0}).z, 1.0f - 2.0f * 1e-3f * r / span, kTol);
    // The ground reaches beyond the map in x and y (only casters need to be in it), never in depth.
    for (const glm::vec3& p : corners({-100, -5, -100}, {100, -5, 100})) {
        const glm::vec3 c = clip(m, p);
        EXPECT_GT(std::abs(c.x), 1.0f);
        EXPECT_LT(std::abs(c.z), 1.0f);
    }
    // Oblique lights: no closed form worth writing out, but the same two properties.
    for (glm::vec3 dir : {glm::vec3(-0.4f, -1, -0.3f), glm::vec3(1, -0.2f, 0), glm::vec3(0.3f, -1, 0.2f)}) {
        SCOPED_TRACE(dir.x);
        const Light light = directional(dir);
        const glm::mat4 oblique = fitLightViewProjection(scene, light);
        glm::vec2 lo(1e9f), hi(-1e9f);
        for (const glm::vec3& p : corners({-30, 0, -20}, {40, 12, 25})) {
            const glm::vec3 c = clip(oblique, p);
            lo = glm::min(lo, glm::vec2(c));
            hi = glm::max(hi, glm::vec2(c));
        }
        // Inside, and the extreme corners within the padding of the edges: 1% of the extent + 1e-3
        // each side leaves at least 1 / 1.02 of the half width (extents here are above 10, so the
        // 1e-3 adds under 2e-4).
        for (int a = 0; a < 2; ++a) {
            EXPECT_GE(lo[a], -1.0f) << "axis " << a;
            EXPECT_LE(hi[a], 1.0f) << "axis " << a;
            EXPECT_LT(lo[a], -1.0f / 1.0202f) << "axis " << a;
            EXPECT_GT(hi[a], 1.0f / 1.0202f) << "axis " << a;
        }
        for (const glm::vec3& p : corners({-100, -5, -100}, {100, -5, 100}))
            EXPECT_LT(std::abs(clip(oblique, p).z), 1.0f) << "receiver corners stay inside the depth range";
        const glm::vec3 centre(5, 6, 2.5f);
        EXPECT_GT(clip(oblique, centre + light.direction).z, clip(oblique, centre).z)
            << "depth grows along the light";
    }
}

TEST(LightFitTest, SpotIsTheConeBetweenTheScenesNearestAndFarthestPoints) {
    Scene scene;
    addBox(scene, {-3, 0, -3}, {3, 5, 3}, true);
    Light light;
    light.type = LightType::Spot;
    light.position = {0, 20, 0};
    light.direction = {0, -1, 0};
    light.spotOuterDeg = 30.0f;
    const glm::mat4 m = fitLightViewProjection(scene, light);
    // fov = 2 x 30 degrees: at depth 10 on the axis, 10 tan(30) off it is the frustum's edge.
    const glm::vec3 onEdge = clip(m, {0, 10, 10.0f * std::tan(glm::radians(30.0f))});
    EXPECT_NEAR(std::max(std::abs(onEdge.x), std::abs(onEdge.y)), 1.0f, kTol);
    // Near at the box's top (depth 15), far at its bottom (depth 20), exactly.
    EXPECT_NEAR(clip(m, {0, 5, 0}).z, -1.0f, kTol);
    EXPECT_NEAR(clip(m, {0, 0, 0}).z, 1.0f, kTol);
    for (const glm::vec3& p : corners({-3, 0, -3}, {3, 5, 3})) {
        const glm::vec3 c = clip(m, p);
        for (int a = 0; a < 3; ++a) EXPECT_LE(std::abs(c[a]), 1.0f + kTol) << "axis " << a;
    }
}

TEST(LightFitTest, SpotInsideTheSceneKeepsItsNearPlanePositive) {
    Scene scene;
    addBox(scene, {-5, -5, -5}, {5, 5, 5}, true);
    Light light;
    light.type = LightType::Spot;
    light.position = {0, 1, 0};
    light.direction = {0, -1, 0};
    const glm::mat4 m = fitLightViewProjection(scene, light);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_TRUE(std::isfinite(m[c][r]));
    // The box's top is 4 behind the light, its bottom 6 in front: far = 6 and the near plane, which
    // would be at -4, is clamped to 1e-3 x far = 0.006 in front of the light.
    EXPECT_NEAR(clip(m, {0, 1.0f - 0.006f, 0}).z, -1.0f, kTol);
    EXPECT_NEAR(clip(m, {0, -5, 0}).z, 1.0f, kTol);
    EXPECT_GT((m * glm::vec4(0, 0.5f, 0, 1)).w, 0.0f) << "a point just in front of the light is in front";
}
