// Unit tests of scenes/Math: each expectation is checked against a matrix or point built by hand
// from the definitions (not through GLM's helpers that the implementation uses).
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "scenes/Math.h"

using namespace sb;

namespace {

// Single-precision trig and products: 1e-5 is a few ulps of values of magnitude ~1-10.
constexpr float kTol = 1e-5f;

glm::mat4 rotX(float deg) {
    const float c = std::cos(glm::radians(deg)), s = std::sin(glm::radians(deg));
    glm::mat4 m(1.0f); // column-major: m[column][row]
    m[1][1] = c;
    m[1][2] = s;
    m[2][1] = -s;
    m[2][2] = c;
    return m;
}
glm::mat4 rotY(float deg) {
    const float c = std::cos(glm::radians(deg)), s = std::sin(glm::radians(deg));
    glm::mat4 m(1.0f);
    m[0][0] = c;
    m[0][2] = -s;
    m[2][0] = s;
    m[2][2] = c;
    return m;
}
glm::mat4 rotZ(float deg) {
    const float c = std::cos(glm::radians(deg)), s = std::sin(glm::radians(deg));
    glm::mat4 m(1.0f);
    m[0][0] = c;
    m[0][1] = s;
    m[1][0] = -s;
    m[1][1] = c;
    return m;
}

void expectMatNear(const glm::mat4& a, const glm::mat4& b, float tol) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(a[c][r], b[c][r], tol) << "column " << c << " row " << r;
}

glm::vec3 clip(const glm::mat4& m, const glm::vec3& p) {
    const glm::vec4 c = m * glm::vec4(p, 1.0f);
    EXPECT_GT(c.w, 0.0f);
    return glm::vec3(c) / c.w;
}

} // namespace

TEST(MathTest, ComposeTransformMatchesHandBuiltTRxRyRzS) {
    const glm::vec3 pos(1.5f, -2.0f, 3.25f), rot(30.0f, -45.0f, 60.0f);
    const float scale = 2.5f;
    glm::mat4 t(1.0f);
    t[3] = glm::vec4(pos, 1.0f);
    glm::mat4 s(1.0f);
    s[0][0] = s[1][1] = s[2][2] = scale;
    expectMatNear(composeTransform(pos, rot, scale), t * rotX(rot.x) * rotY(rot.y) * rotZ(rot.z) * s, kTol);
}

TEST(MathTest, ComposeTransformMovesAPointAsWorkedOutByHand) {
    // (1,0,0) scaled by 2 -> (2,0,0); yaw +90 about Y maps +X to -Z -> (0,0,-2); plus (1,2,3) -> (1,2,1).
    const glm::vec4 p = composeTransform({1, 2, 3}, {0, 90, 0}, 2.0f) * glm::vec4(1, 0, 0, 1);
    EXPECT_NEAR(p.x, 1.0f, kTol);
    EXPECT_NEAR(p.y, 2.0f, kTol);
    EXPECT_NEAR(p.z, 1.0f, kTol);
    // The order matters: Z first, then Y. (0,1,0) under Rz(90) -> (-1,0,0), then Ry(90) -> (0,0,1).
    const glm::vec4 q = composeTransform({0, 0, 0}, {0, 90, 90}, 1.0f) * glm::vec4(0, 1, 0, 1);
    EXPECT_NEAR(q.x, 0.0f, kTol);
    EXPECT_NEAR(q.y, 0.0f, kTol);
    EXPECT_NEAR(q.z, 1.0f, kTol);
}

TEST(MathTest, TransformBoundsOfRotatedAndMovedUnitBox) {
    Aabb unit;
    unit.extend(glm::vec3(-1.0f));
    unit.extend(glm::vec3(1.0f));
    // A 45 degree yaw turns the square's corners onto the axes: x and z extents become +-sqrt(2).
    const Aabb b = transformBounds(unit, composeTransform({10, 0, -5}, {0, 45, 0}, 1.0f));
    const float r2 = std::sqrt(2.0f);
    EXPECT_NEAR(b.min.x, 10 - r2, kTol);
    EXPECT_NEAR(b.max.x, 10 + r2, kTol);
    EXPECT_NEAR(b.min.y, -1.0f, kTol);
    EXPECT_NEAR(b.max.y, 1.0f, kTol);
    EXPECT_NEAR(b.min.z, -5 - r2, kTol);
    EXPECT_NEAR(b.max.z, -5 + r2, kTol);
    EXPECT_TRUE(transformBounds(Aabb{}, glm::mat4(1.0f)).empty());
}

TEST(MathTest, CameraMatricesAreTheGlConventionOnes) {
    CameraPreset c;
    c.eye = {0, 0, 5};
    c.target = {0, 0, 0};
    c.fovYDeg = 90.0f;
    c.nearZ = 1.0f;
    c.farZ = 10.0f;
    // With fov 90 and aspect 2 a point at view depth d and height d is on the top edge (y_ndc = 1), at
    // x = 2d on the right edge; the near plane maps to z = -1 and the far plane to z = +1.
    const glm::mat4 vp = cameraProjection(c, 2.0f) * cameraView(c);
    EXPECT_NEAR(clip(vp, {0, 3, 2}).y, 1.0f, kTol);
    EXPECT_NEAR(clip(vp, {6, 0, 2}).x, 1.0f, kTol);
    EXPECT_NEAR(clip(vp, {0, 0, 4}).z, -1.0f, kTol);
    EXPECT_NEAR(clip(vp, {0, 0, -5}).z, 1.0f, 1e-4f);
}

TEST(MathTest, AnyPerpendicularUpIsNeverParallel) {
    for (glm::vec3 d : {glm::vec3(0, -1, 0), glm::vec3(0, 1, 0), glm::vec3(1, 0, 0),
                        glm::vec3(0.3f, -1, 0.2f), glm::vec3(0, 0, 1), glm::vec3(0.01f, -1, 0)}) {
        const glm::vec3 up = anyPerpendicularUp(d);
        EXPECT_NEAR(glm::length(up), 1.0f, kTol);
        // sin of the angle between them must be clearly non-zero for lookAt to be well conditioned.
        EXPECT_GT(glm::length(glm::cross(glm::normalize(d), up)), 0.1f);
    }
}
