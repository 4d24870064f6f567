#pragma once
// The closed form `shadowmap` is judged against on both APIs (tests/ShadowMapGLTest.cpp on GL,
// tests/ShadowMapVkTest.cpp on Vulkan): the shadow of a sphere on a plane under a directional light is
// an exact ellipse; a ground point p is in it iff the ray p - t*L (towards the light) passes within r of
// the sphere's centre. Every ground pixel's world position comes from the depth buffer, so each pixel
// is judged against the exact answer at its own sample position.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "scenes/LightFit.h"
#include "scenes/Math.h"
#include "scenes/Scene.h"
#include "techniques/PropertySet.h"

namespace sb::test {

// Distance from the sphere centre c to the ray from p towards the light, minus the radius: negative
// inside the shadow ellipse, positive outside, in world units perpendicular to the light.
inline double shadowMargin(const glm::dvec3& p, const glm::dvec3& toLight, const glm::dvec3& c, double r) {
    glm::dvec3 pc = c - p;
    double t = glm::dot(pc, toLight);
    if (t <= 0.0) return 1e9; // the sphere is behind the point (below the plane): no shadow
    return glm::length(pc - t * toLight) - r;
}

/// The sphere of sphere_plane: centre and radius from its instance and geometry.
inline bool findSphere(const Scene& scene, glm::dvec3& centre, double& radius) {
    const Instance* sphere = nullptr;
    for (const Instance& i : scene.instances)
        if (i.castsShadow) sphere = &i;
    if (!sphere) return false;
    double meshRadius = 0.0;
    for (const glm::vec3& p : scene.meshes[sphere->mesh].positions)
        meshRadius = std::max(meshRadius, double(glm::length(p)));
    centre = glm::dvec3(sphere->model * glm::vec4(0, 0, 0, 1));
    radius = meshRadius * sphere->scale;
    return true;
}

/// Judges one rendered frame of sphere_plane (tessellation 64, directional light) at size x size:
/// `depth` and `vis` as the targets read them back (rows bottom-up), `viewProj` the camera's. `band`:
/// the technique's own tolerance around the ellipse's edge in world units perpendicular to the light
/// (a map's texels; 0 for exact techniques); the polygonal silhouette and the pixel footprint are added.
inline void judgeSphereShadow(const Scene& scene, double techniqueBand, const std::vector<float>& depth,
                              const std::vector<float>& vis, const glm::mat4& viewProj, int kSize) {
    glm::dvec3 centre;
    double radius = 0.0;
    ASSERT_TRUE(findSphere(scene, centre, radius));
    glm::dvec3 toLight = -glm::normalize(glm::dvec3(scene.lights[0].direction));
    const double band = techniqueBand + radius * (1.0 - std::cos(M_PI / 64.0));
    auto world = unprojectDepth(depth, kSize, kSize, viewProj);
    int ground = 0, shadowedExpected = 0, shadowedGot = 0, judged = 0, wrong = 0;
    for (int y = 1; y < kSize - 1; ++y)
        for (int x = 1; x < kSize - 1; ++x) {
            size_t i = size_t(y) * kSize + size_t(x);
            if (world[i].w == 0.0f || std::abs(world[i].y) > 1e-2f) continue; // ground pixels only
            ++ground;
            double footprint = glm::length(glm::vec3(world[i + 1]) - glm::vec3(world[i]));
            double margin = shadowMargin(glm::dvec3(world[i]), toLight, centre, radius);
            bool expectShadow = margin < 0.0;
            bool gotShadow = vis[i * 4] < 0.5f;
            shadowedExpected += expectShadow;
            shadowedGot += gotShadow;
            if (std::abs(margin) <= band + footprint) continue; // the edge band: either answer is right
            ++judged;
            if (expectShadow != gotShadow) {
                ++wrong;
                if (wrong <= 5)
                    ADD_FAILURE() << "pixel (" << x << "," << y << ") world " << world[i].x << ","
                                  << world[i].z << " margin " << margin << " expected "
                                  << (expectShadow ? "shadow" : "lit") << " got visibility " << vis[i * 4];
            }
        }
    // The ellipse must be substantially in view, or the test proves nothing.
    EXPECT_GT(ground, kSize * kSize / 4);
    EXPECT_GT(shadowedExpected, 500) << "the analytic shadow hardly covers any pixel";
    EXPECT_GT(judged, ground * 9 / 10) << "the tolerance band swallowed the image";
    EXPECT_EQ(wrong, 0) << "pixels outside the edge band classified wrongly (band " << band
                        << " world units)";
    // Shadow area agrees with the ellipse's within the band's share of pixels.
    EXPECT_NEAR(double(shadowedGot), double(shadowedExpected), 0.05 * shadowedExpected + 50);
}

/// `shadowmap`'s band: the map's texel (plus the PCF half-width, and one texel for bilinear hardware
/// compare), from the fitted orthographic light camera and `properties` (resolution, pcf).
inline double shadowMapBand(const Scene& scene, const PropertySet& properties) {
    glm::mat4 lightVP = fitLightViewProjection(scene, scene.lights[0]);
    // Orthographic light: row i of proj*view is (2 / extent_i) times a unit axis, so the extent of the
    // map in world units is 2 / |row|.
    auto rowLength = [&](int r) {
        return glm::length(glm::vec3(lightVP[0][r], lightVP[1][r], lightVP[2][r]));
    };
    const double orthoWidth = 2.0 / std::min(rowLength(0), rowLength(1));
    const double texel = orthoWidth / double(properties.getInt("resolution"));
    return texel * (1.5 + 0.5 * double(properties.getInt("pcf")));
}

} // namespace sb::test
