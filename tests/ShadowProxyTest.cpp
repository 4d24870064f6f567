// Unit tests of scenes/ShadowProxy: Listing 1.1's closest points against the closed forms of the three
// shapes (sphere: radial projection; box: clamping; cylinder: radial clamp plus cap), the points the
// hard cases name (inside, on the surface, the centre), normals, the tightest-fit choice on generated
// meshes, and Listing 1.3 with ProxyOffset 0 and 1e-9.
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "scenes/MeshGenerators.h"
#include "scenes/ShadowProxy.h"

using namespace sb;

namespace {

ShadowProxy proxy(ShadowProxy::Shape shape, const glm::vec3& position, const glm::vec3& size,
                  float yawDeg = 0.0f) {
    ShadowProxy p;
    p.shape = shape;
    p.frame = glm::scale(
        glm::rotate(glm::translate(glm::mat4(1.0f), position), glm::radians(yawDeg), glm::vec3(0, 1, 0)),
        size);
    return p;
}

void expectNear(const glm::vec3& a, const glm::vec3& b, float tol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

} // namespace

TEST(ShadowProxyTest, SphereClosestPointIsTheRadialProjection) {
    const ShadowProxy s = proxy(ShadowProxy::Shape::Sphere, {1, 2, 3}, glm::vec3(2.0f));
    for (const glm::vec3& p : {glm::vec3(5, 2, 3), glm::vec3(-1, 7, 0.5f), glm::vec3(1.5f, 2.2f, 2.9f)}) {
        const glm::vec3 expected = glm::vec3(1, 2, 3) + 2.0f * glm::normalize(p - glm::vec3(1, 2, 3));
        expectNear(s.closestPoint(p), expected, 1e-5f);
        expectNear(s.surfaceNormal(p), glm::normalize(p - glm::vec3(1, 2, 3)), 1e-5f);
    }
    // The centre: normalize(0) would be NaN; the top of the sphere instead.
    const glm::vec3 c = s.closestPoint({1, 2, 3});
    EXPECT_TRUE(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z));
    EXPECT_NEAR(glm::length(c - glm::vec3(1, 2, 3)), 2.0f, 1e-5f);
}

TEST(ShadowProxyTest, BoxClosestPointClampsAndInsideIsItself) {
    // Box of half extents (1, 0.5, 2) at the origin, turned 30 degrees about y: compare in the box's
    // own frame, where the closest point is the clamp to the extents.
    const ShadowProxy b = proxy(ShadowProxy::Shape::Box, {0, 0, 0}, {1, 0.5f, 2}, 30.0f);
    const glm::mat4 toLocal = glm::rotate(glm::mat4(1.0f), glm::radians(-30.0f), glm::vec3(0, 1, 0));
    for (const glm::vec3& local :
         {glm::vec3(3, 0.2f, -1), glm::vec3(-0.5f, 2, 5), glm::vec3(0.3f, -0.1f, 0.4f)}) {
        const glm::vec3 world = glm::vec3(glm::inverse(toLocal) * glm::vec4(local, 1.0f));
        const glm::vec3 clamped = glm::clamp(local, glm::vec3(-1, -0.5f, -2), glm::vec3(1, 0.5f, 2));
        const glm::vec3 got = glm::vec3(toLocal * glm::vec4(b.closestPoint(world), 1.0f));
        expectNear(got, clamped, 1e-5f);
    }
    // Inside: distance 0 (the fragment is in the proxy: full shadow, Listing 1.3 gives 1).
    const glm::vec3 inside(0.2f, 0.1f, -0.3f);
    EXPECT_NEAR(glm::length(b.closestPoint(inside) - inside), 0.0f, 1e-6f);
    // Normal on the +x face of the box from outside in front of it.
    const glm::vec3 n = b.surfaceNormal(glm::vec3(glm::inverse(toLocal) * glm::vec4(3, 0, 0, 1)));
    expectNear(glm::vec3(toLocal * glm::vec4(n, 0.0f)), {1, 0, 0}, 1e-5f);
}

TEST(ShadowProxyTest, CylinderClosestPointOnSideCapAndRim) {
    // Radius 1.5 around z (local), half height 2.
    const ShadowProxy c = proxy(ShadowProxy::Shape::Cylinder, {0, 0, 0}, {1.5f, 1.5f, 2});
    expectNear(c.closestPoint({3, 0, 1}), {1.5f, 0, 1}, 1e-5f);          // side
    expectNear(c.closestPoint({0.5f, 0.2f, 5}), {0.5f, 0.2f, 2}, 1e-5f); // cap
    expectNear(c.closestPoint({3, 4, -6}), {0.9f, 1.2f, -2}, 1e-5f);     // rim: radial 5 -> 1.5
    expectNear(c.surfaceNormal({3, 0, 1}), {1, 0, 0}, 1e-5f);
    expectNear(c.surfaceNormal({0.5f, 0.2f, 5}), {0, 0, 1}, 1e-5f);
}

TEST(ShadowProxyTest, FitPicksTheTightestShape) {
    // A sphere mesh gets a sphere (4.19 r^3 against the box's 8 r^3 and the cylinder's 6.28 r^3), a
    // box a box, a long cylinder a cylinder; each proxy contains every vertex (distance to the local
    // unit shape <= 1 + 1e-5).
    struct Case {
        Mesh mesh;
        ShadowProxy::Shape expected;
    };
    Mesh longCylinder = MeshGenerators::cylinder(24);
    for (glm::vec3& p : longCylinder.positions) p.y *= 3.0f; // 6 long, radius 1
    const Case cases[] = {{MeshGenerators::sphere(24), ShadowProxy::Shape::Sphere},
                          {MeshGenerators::box(glm::vec3(1.0f, 0.4f, 2.0f), 2), ShadowProxy::Shape::Box},
                          {longCylinder, ShadowProxy::Shape::Cylinder}};
    const glm::mat4 model = glm::translate(glm::mat4(1.0f), glm::vec3(4, 1, -2));
    for (const Case& c : cases) {
        const ShadowProxy p = ShadowProxy::fit(c.mesh, model);
        EXPECT_EQ(p.shape, c.expected) << ShadowProxy::shapeName(p.shape);
        const glm::mat4 inv = glm::inverse(p.frame);
        for (const glm::vec3& v : c.mesh.positions) {
            const glm::vec3 local(inv * model * glm::vec4(v, 1.0f));
            float norm = 0.0f;
            switch (p.shape) {
            case ShadowProxy::Shape::Sphere:
                norm = glm::length(local);
                break;
            case ShadowProxy::Shape::Box:
                norm = std::max({std::abs(local.x), std::abs(local.y), std::abs(local.z)});
                break;
            case ShadowProxy::Shape::Cylinder:
                norm = std::max(glm::length(glm::vec2(local)), std::abs(local.z));
                break;
            }
            ASSERT_LE(norm, 1.0f + 1e-5f) << ShadowProxy::shapeName(p.shape);
        }
    }
}

TEST(ShadowProxyTest, Listing13WithZeroAndTinyProxyOffset) {
    // Hand-computed: offset 2, distance 0.5 -> 1 - 0.25 = 0.75, times 0.8^2 = 0.64 -> 0.48.
    EXPECT_NEAR(proxyShadow(0.5f, 2.0f, 0.8f, 2.0f), 0.48f, 1e-6f);
    EXPECT_NEAR(proxyShadow(3.0f, 2.0f, 0.8f, 2.0f), 0.0f, 1e-6f); // beyond the offset
    EXPECT_NEAR(proxyShadow(0.0f, 2.0f, 1.0f, 1.0f), 1.0f, 1e-6f); // on the surface
    // ProxyOffset 0: no division by zero; on the surface full, elsewhere none.
    EXPECT_EQ(proxyShadow(0.0f, 0.0f, 1.0f, 1.0f), 1.0f);
    EXPECT_EQ(proxyShadow(1e-3f, 0.0f, 1.0f, 1.0f), 0.0f);
    // 1e-9: finite, and the same step at the scale of the offset.
    for (float d : {0.0f, 5e-10f, 2e-9f, 1.0f}) {
        const float s = proxyShadow(d, 1e-9f, 1.0f, 1.0f);
        EXPECT_TRUE(std::isfinite(s));
        EXPECT_NEAR(s, 1.0f - std::min(d / 1e-9f, 1.0f), 1e-5f);
    }
}
