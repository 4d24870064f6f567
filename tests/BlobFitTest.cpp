// BlobGL::fit against hand-computed ellipses: the bounds' corners projected along the light,
// centred on their mean, principal axes, semi-axes sqrt(2) standard deviations (through the corners of
// a rectangular footprint), opacity falling linearly with height.
#include <cmath>

#include <gtest/gtest.h>

#include "scenes/Scene.h"
#include "techniques/blob/BlobGL.h"

using namespace sb;

namespace {
ReceiverPlane ground() {
    ReceiverPlane g; // y = 0 facing up
    g.normal = {0, 1, 0};
    g.d = 0;
    return g;
}
Aabb box(glm::vec3 lo, glm::vec3 hi) {
    Aabb b;
    b.extend(lo);
    b.extend(hi);
    return b;
}
Light sun(glm::vec3 dir) {
    Light l;
    l.direction = glm::normalize(dir);
    return l;
}
float axisLength(const glm::vec4& a) {
    return glm::length(glm::vec3(a));
}
} // namespace

TEST(BlobFitTest, OverheadSunGivesTheFootprint) {
    // A 2x2x2 box from y = 2 to 4 under a sun straight down: the footprint [-1, 1]^2 (variance 1 on
    // every axis), the circle through its corners: radius sqrt(2) at the origin.
    const auto b = BlobGL::fit(box({-1, 2, -1}, {1, 4, 1}), ground(), sun({0, -1, 0}), 0, 1.0f, 0.5f, 8.0f);
    ASSERT_TRUE(b);
    EXPECT_NEAR(glm::length(glm::vec3(b->centre)), 0.0f, 1e-5f);
    EXPECT_NEAR(axisLength(b->axisU), std::sqrt(2.0f), 1e-5f);
    EXPECT_NEAR(axisLength(b->axisV), std::sqrt(2.0f), 1e-5f);
    EXPECT_NEAR(glm::dot(glm::vec3(b->axisU), glm::vec3(b->axisV)), 0.0f, 1e-5f);
    // Opacity: bottom 2 above the ground, bounding radius sqrt(3), fade 8 radii.
    EXPECT_NEAR(b->centre.w, 1.0f - 2.0f / (8.0f * std::sqrt(3.0f)), 1e-5f);
    EXPECT_EQ(b->axisU.w, 0.0f); // light index
    EXPECT_EQ(b->axisV.w, 0.5f); // softness
}

TEST(BlobFitTest, ObliqueSunStretchesAlongTheLight) {
    // Sun along (1, -1, 0): a corner at height h moves +h in x: x = 1, 3, 3, 5 (mean 3, variance 2),
    // z = +-1 (variance 1): centre (3, 0, 0), semi-axes 2 along x and sqrt(2) along z.
    const auto b = BlobGL::fit(box({-1, 2, -1}, {1, 4, 1}), ground(), sun({1, -1, 0}), 2, 1.0f, 0.0f, 8.0f);
    ASSERT_TRUE(b);
    EXPECT_NEAR(glm::distance(glm::vec3(b->centre), glm::vec3(3, 0, 0)), 0.0f, 1e-4f);
    const glm::vec3 u(b->axisU), v(b->axisV);
    const glm::vec3 major = axisLength(b->axisU) > axisLength(b->axisV) ? u : v;
    const glm::vec3 minor = axisLength(b->axisU) > axisLength(b->axisV) ? v : u;
    EXPECT_NEAR(glm::length(major), 2.0f, 1e-4f);
    EXPECT_NEAR(std::abs(major.x), 2.0f, 1e-4f);
    EXPECT_NEAR(glm::length(minor), std::sqrt(2.0f), 1e-4f);
    EXPECT_NEAR(std::abs(minor.z), std::sqrt(2.0f), 1e-4f);
    EXPECT_EQ(b->axisU.w, 2.0f);
}

TEST(BlobFitTest, PointLightProjectsFromItsPosition) {
    // A point light at (0, 8, 0) over a box x in [3, 5], y in [2, 4], z in [-1, 1]: a corner at height
    // h lands at (x, z) * 8 / (8 - h): x = 4, 6.667 (h = 2), 6, 10 (h = 4): mean 6.667, variance 4.667;
    // z = +-1.333 (h = 2), +-2 (h = 4): variance 2.889. Semi-axes sqrt(9.333) and sqrt(5.778).
    Light l;
    l.type = LightType::Point;
    l.position = {0, 8, 0};
    const auto b = BlobGL::fit(box({3, 2, -1}, {5, 4, 1}), ground(), l, 0, 1.0f, 0.5f, 8.0f);
    ASSERT_TRUE(b);
    EXPECT_NEAR(b->centre.x, 20.0f / 3.0f, 1e-4f);
    EXPECT_NEAR(b->centre.z, 0.0f, 1e-4f);
    EXPECT_NEAR(std::max(axisLength(b->axisU), axisLength(b->axisV)), std::sqrt(2.0f * 14.0f / 3.0f), 1e-4f);
    EXPECT_NEAR(std::min(axisLength(b->axisU), axisLength(b->axisV)), std::sqrt(2.0f * 26.0f / 9.0f), 1e-4f);
}

TEST(BlobFitTest, SquareFootprintIsStableUnderRotation) {
    // The same 2x2 footprint turned by small angles: the principal axes jump, the circle must not.
    for (float deg : {0.0f, 1e-4f, 0.01f, 30.0f, 45.0f}) {
        const float c = std::cos(glm::radians(deg)), s = std::sin(glm::radians(deg));
        Aabb b;
        for (int i = 0; i < 8; ++i) {
            const float x = (i & 1) ? 1.0f : -1.0f, z = (i & 4) ? 1.0f : -1.0f;
            b.extend(glm::vec3(c * x - s * z, (i & 2) ? 4.0f : 2.0f, s * x + c * z));
        }
        // The bounds of a turned square are a bigger square: half extent c + s.
        const float half = c + s;
        const auto blob = BlobGL::fit(b, ground(), sun({0, -1, 0}), 0, 1, 0.5f, 8);
        ASSERT_TRUE(blob);
        EXPECT_NEAR(axisLength(blob->axisU), std::sqrt(2.0f) * half, 1e-4f) << deg;
        EXPECT_NEAR(axisLength(blob->axisV), std::sqrt(2.0f) * half, 1e-4f) << deg;
    }
}

TEST(BlobFitTest, NoBlobWhereNoShadowCanBe) {
    const Aabb b = box({-1, 2, -1}, {1, 4, 1});
    Light below;
    below.type = LightType::Point;
    below.position = {0, -3, 0};
    EXPECT_FALSE(BlobGL::fit(b, ground(), below, 0, 1, 0.5f, 8));          // light under the ground
    EXPECT_FALSE(BlobGL::fit(b, ground(), sun({1, 0, 0}), 0, 1, 0.5f, 8)); // light in its plane
    EXPECT_FALSE(BlobGL::fit(box({-1, -4, -1}, {1, -2, 1}), ground(), sun({0, -1, 0}), 0, 1, 0.5f, 8));
    EXPECT_FALSE(BlobGL::fit(b, ground(), sun({0, -1, 0}), 0, 1, 0.5f, 0.5f));   // faded out (2 > 0.87)
    EXPECT_FALSE(BlobGL::fit(Aabb{}, ground(), sun({0, -1, 0}), 0, 1, 0.5f, 8)); // empty bounds
    Light under;
    under.type = LightType::Point;
    under.position = {0, 1.5f, 0}; // between the ground and the box's bottom (y = 2)
    EXPECT_FALSE(BlobGL::fit(b, ground(), under, 0, 1, 0.5f, 8));
}
