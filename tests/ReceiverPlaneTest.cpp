// scenes/ReceiverPlane: which instances are receiver planes, and the slides' flattening matrix against
// the slides' own vector formula and their printed 4x4 matrix for the plane y = 0.
#include <cmath>

#include <gtest/gtest.h>

#include "core/SplitMix64.h"
#include "scenes/Math.h"
#include "scenes/MeshGenerators.h"
#include "scenes/ReceiverPlane.h"
#include "scenes/Scene.h"

using namespace sb;

namespace {
Instance instance(uint32_t mesh, glm::vec3 pos, glm::vec3 rot, bool casts) {
    Instance i;
    i.mesh = mesh;
    i.position = pos;
    i.rotationDeg = rot;
    i.castsShadow = casts;
    i.color = glm::vec3(0.25f, 0.5f, 0.75f);
    return i;
}
} // namespace

TEST(ReceiverPlaneTest, PlanarNonCastingReceiversAreFound) {
    Scene s;
    s.meshes = {MeshGenerators::plane(10.0f, 4), MeshGenerators::sphere(8)};
    s.instances = {instance(0, {0, 0, 0}, {0, 0, 0}, false),    // the ground
                   instance(0, {-5, 5, 0}, {0, 0, -90}, false), // a wall at x = -5 facing +x
                   instance(0, {0, 2, 0}, {0, 0, 0}, true),     // a plane that casts: not a receiver
                   instance(1, {0, 1, 0}, {0, 0, 0}, false)};   // not planar
    s.updateTransforms();
    const std::vector<ReceiverPlane> planes = ReceiverPlane::find(s);
    ASSERT_EQ(planes.size(), 2u);
    EXPECT_EQ(planes[0].instance, 0u);
    EXPECT_NEAR(glm::distance(planes[0].normal, glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
    EXPECT_NEAR(planes[0].d, 0.0f, 1e-6f);
    EXPECT_EQ(planes[0].albedo, glm::vec3(0.25f, 0.5f, 0.75f));
    EXPECT_EQ(planes[1].instance, 1u);
    EXPECT_NEAR(glm::distance(planes[1].normal, glm::vec3(1, 0, 0)), 0.0f, 1e-6f);
    EXPECT_NEAR(planes[1].d, 5.0f, 1e-5f);
    // The rectangle is the plane's extent (10 x 10), counter-clockwise seen from the front.
    for (const ReceiverPlane& p : planes) {
        for (const glm::vec3& c : p.corners) EXPECT_NEAR(p.distance(c), 0.0f, 1e-5f);
        EXPECT_NEAR(glm::distance(p.corners[0], p.corners[1]), 10.0f, 1e-4f);
        EXPECT_NEAR(glm::distance(p.corners[1], p.corners[2]), 10.0f, 1e-4f);
        const glm::vec3 n = glm::cross(p.corners[1] - p.corners[0], p.corners[2] - p.corners[1]);
        EXPECT_GT(glm::dot(n, p.normal), 0.0f);
    }
}

TEST(ReceiverPlaneTest, ProjectionIsTheSlidesFormula) {
    // v' = l - (d + n.l) / (n.(v - l)) (v - l) for random planes, lights and vertices.
    SplitMix64 rng(8);
    auto u = [&] { return float(rng.uniform() * 2.0 - 1.0); };
    for (int k = 0; k < 200; ++k) {
        ReceiverPlane p;
        p.normal = glm::normalize(glm::vec3(u(), u(), u()) + glm::vec3(0, 2, 0));
        p.d = 3.0f * u();
        const glm::vec3 l = glm::vec3(5 * u(), 6 + 2 * u(), 5 * u());
        const glm::vec3 v = glm::vec3(3 * u(), 2 + u(), 3 * u());
        const glm::vec4 h = p.projection({l, 1.0f}) * glm::vec4(v, 1.0f);
        const glm::vec3 got = glm::vec3(h) / h.w;
        const glm::vec3 want = l - (p.d + glm::dot(p.normal, l)) / glm::dot(p.normal, v - l) * (v - l);
        // float rounding of a 4x4 product and a division: relative 1e-4 of the coordinates' size.
        EXPECT_NEAR(glm::distance(got, want), 0.0f, 1e-4f * (1.0f + glm::length(want)));
        EXPECT_NEAR(p.distance(got), 0.0f, 1e-4f * (1.0f + glm::length(want)));
    }
}

TEST(ReceiverPlaneTest, GroundPlaneMatrixIsTheSlidesMatrix) {
    ReceiverPlane p; // y = 0
    const glm::vec3 l(1.5f, 4.0f, -2.0f);
    const glm::mat4 m = p.projection({l, 1.0f});
    // The slides' rows: (ly, -lx, 0, 0), (0, 0, 0, 0), (0, -lz, ly, 0), (0, -1, 0, ly); glm is m[col][row].
    const float rows[4][4] = {{l.y, -l.x, 0, 0}, {0, 0, 0, 0}, {0, -l.z, l.y, 0}, {0, -1, 0, l.y}};
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) EXPECT_FLOAT_EQ(m[c][r], rows[r][c]) << "row " << r << " col " << c;
}

TEST(ReceiverPlaneTest, DirectionalLightProjectsAlongItsDirection) {
    ReceiverPlane p;
    p.normal = glm::vec3(0, 1, 0);
    p.d = -1.0f; // y = 1
    Light sun;
    sun.direction = glm::normalize(glm::vec3(1, -2, 0.5f));
    const glm::vec4 l = ReceiverPlane::homogeneousLight(sun);
    EXPECT_EQ(l.w, 0.0f);
    EXPECT_GT(p.lightSide(l), 0.0f);
    const glm::vec3 v(0.3f, 4.0f, -0.7f);
    const glm::vec4 h = p.projection(l) * glm::vec4(v, 1.0f);
    const glm::vec3 got = glm::vec3(h) / h.w;
    // Travel 3 units down along the direction: t = 3 / 2 per unit of direction's y.
    const glm::vec3 want = v + sun.direction * (3.0f / -sun.direction.y);
    EXPECT_NEAR(glm::distance(got, want), 0.0f, 1e-5f);
}
