// Unit tests of scenes/ShadowPlane: equations 6 and 8 of the occluder-texture thesis against
// hand-computed hits, against the appendix's own z = 0 shortcut (equation 7) and tail-fin code with
// its constants, the false-shadow sign, the parallel-light guard, and the affinity that lets the
// vertex shader compute coordinates per vertex and the rasteriser interpolate them exactly.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "core/Error.h"
#include "scenes/ShadowPlane.h"

using namespace sb;

namespace {

ShadowPlane zPlane(float size) {
    ShadowPlane p;
    p.name = "z0";
    p.origin = glm::vec3(0.0f);
    p.normal = glm::vec3(0, 0, 1);
    p.right = glm::vec3(1, 0, 0);
    p.up = glm::vec3(0, 1, 0);
    p.width = p.height = size;
    return p;
}

bool finite(const ShadowCoord& c) {
    return std::isfinite(c.s) && std::isfinite(c.uv.x) && std::isfinite(c.uv.y);
}

} // namespace

TEST(ShadowPlaneTest, HandComputedHits) {
    const ShadowPlane p = zPlane(2.0f);
    // Light straight up (+z), point 2 below the plane: s = 2, hit (0.25, 0.5, 0), uv / 2.
    ShadowCoord c = p.project({0.25f, 0.5f, -2.0f}, {0, 0, 1});
    EXPECT_FLOAT_EQ(c.s, 2.0f);
    EXPECT_FLOAT_EQ(c.uv.x, 0.125f);
    EXPECT_FLOAT_EQ(c.uv.y, 0.25f);
    // Above the plane: s = -1, the plane is behind the point (a false shadow if it were used).
    c = p.project({0.25f, 0.5f, 1.0f}, {0, 0, 1});
    EXPECT_FLOAT_EQ(c.s, -1.0f);
    // Oblique light (1, 0, 1)/sqrt2 from (0, 0, -1): s = 1 / (1/sqrt2) = sqrt2, hit (1, 0, 0).
    const glm::vec3 l = glm::normalize(glm::vec3(1, 0, 1));
    c = p.project({0, 0, -1}, l);
    EXPECT_NEAR(c.s, std::sqrt(2.0f), 1e-6f);
    EXPECT_NEAR(c.uv.x, 0.5f, 1e-6f);
    EXPECT_NEAR(c.uv.y, 0.0f, 1e-6f);
    // A point on the plane hits itself at s = 0.
    c = p.project({0.4f, 1.2f, 0.0f}, l);
    EXPECT_EQ(c.s, 0.0f);
    EXPECT_NEAR(c.uv.x, 0.2f, 1e-6f);
    EXPECT_NEAR(c.uv.y, 0.6f, 1e-6f);
}

TEST(ShadowPlaneTest, MatchesTheAppendixZPlaneShortcut) {
    // Appendix A, first plane: V0 = (-7.5, -5.315, 0), N = (0, 0, 1), 15 m square, and the shortcut
    // intersection = p.xy + (-p.z / L.z) L.xy (equation 7), uv = (intersection + (7.5, 5.315)) / 15.
    ShadowPlane p = zPlane(15.0f);
    p.origin = glm::vec3(-7.5f, -5.315f, 0.0f);
    const glm::vec3 lights[] = {glm::normalize(glm::vec3(0.3f, -0.2f, 0.9f)),
                                glm::normalize(glm::vec3(-0.7f, 0.1f, -0.4f))};
    const glm::vec3 points[] = {{1.0f, 2.0f, -0.3f}, {-4.0f, 0.5f, 0.8f}, {6.0f, -5.0f, 0.01f}};
    for (const glm::vec3& l : lights)
        for (const glm::vec3& p0 : points) {
            const glm::vec2 hit = glm::vec2(p0) + (-p0.z / l.z) * glm::vec2(l);
            const glm::vec2 uv = (hit + glm::vec2(7.5f, 5.315f)) / 15.0f;
            const ShadowCoord c = p.project(p0, l);
            EXPECT_NEAR(c.uv.x, uv.x, 1e-6f);
            EXPECT_NEAR(c.uv.y, uv.y, 1e-6f);
            // The appendix's false-shadow coordinate is L.z * p.z, shadowing when < 0, i.e. s > 0.
            EXPECT_EQ(c.s > 0.0f, l.z * p0.z < 0.0f);
        }
}

TEST(ShadowPlaneTest, MatchesTheAppendixRightTailFin) {
    // Appendix A, right tail fin: N = (-0.917594, 0, 0.397518), V0 = (0.899235, -0.676381, -0.706742),
    // up = (0.3975177, 0, 0.91759448), 4.1218186 m square, texcoord.x = -d.y / size (right = -Y),
    // texcoord.y = d . up / size, false-shadow coordinate dot(-s L, L) < 0.
    ShadowPlane fin;
    fin.name = "fin_right";
    fin.normal = glm::vec3(-0.917594f, 0.0f, 0.397518f);
    fin.origin = glm::vec3(0.899235f, -0.676381f, -0.706742f);
    fin.up = glm::vec3(0.3975177f, 0.0f, 0.91759448f);
    fin.right = glm::vec3(0.0f, -1.0f, 0.0f);
    fin.width = fin.height = 4.1218186f;
    EXPECT_NO_THROW(fin.validate("appendix"));
    const glm::vec3 l = glm::normalize(glm::vec3(-0.8f, 0.3f, 0.5f));
    for (const glm::vec3& p0 : {glm::vec3(0.2f, 0.1f, 0.3f), glm::vec3(1.5f, -0.4f, 0.9f)}) {
        const float sI = glm::dot(fin.normal, fin.origin - p0) / glm::dot(fin.normal, l);
        const glm::vec3 d = p0 + l * sI - fin.origin;
        const ShadowCoord c = fin.project(p0, l);
        EXPECT_NEAR(c.uv.x, -d.y / 4.1218186f, 1e-5f);
        EXPECT_NEAR(c.uv.y, glm::dot(d, fin.up) / 4.1218186f, 1e-5f);
        EXPECT_EQ(c.s > 0.0f, glm::dot(-(l * sI), l) < 0.0f);
    }
}

TEST(ShadowPlaneTest, LightParallelToThePlaneStaysFiniteAndDoesNotFlipSides) {
    // Sweep the light to 90 degrees from the normal, +-1e-k radians: s grows like 1 / angle but stays
    // finite, with the side given by the light's side of the plane; exactly parallel gives no NaN.
    const ShadowPlane p = zPlane(2.0f);
    const glm::vec3 p0(0.3f, 0.4f, -0.5f); // below the plane
    for (int k = 1; k <= 12; ++k)
        for (float sign : {1.0f, -1.0f}) {
            const float a = sign * std::pow(10.0f, -float(k));
            const glm::vec3 l(std::cos(a), 0.0f, std::sin(a)); // elevation a above the plane
            const ShadowCoord c = p.project(p0, l);
            ASSERT_TRUE(finite(c)) << "k " << k << " sign " << sign;
            // Light slightly above: the ray from below rises into the plane ahead (s > 0); slightly
            // below: the plane is behind (s < 0). Beyond the guard (|a| < 1e-6) the sign is kept.
            EXPECT_EQ(c.s > 0.0f, sign > 0.0f) << "k " << k;
            EXPECT_GE(std::abs(c.s), 0.5f / std::max(std::abs(a), ShadowPlane::kMinCosine) * 0.99f) << k;
        }
    const ShadowCoord parallel = p.project(p0, {1, 0, 0});
    EXPECT_TRUE(finite(parallel));
    // In the plane and parallel: 0 / 0 in the equation, 0 here (the point is its own hit).
    const ShadowCoord inPlane = p.project({0.3f, 0.4f, 0.0f}, {1, 0, 0});
    EXPECT_TRUE(finite(inPlane));
    EXPECT_EQ(inPlane.s, 0.0f);
}

TEST(ShadowPlaneTest, CoordinatesAreAffineSoPerVertexInterpolationIsExact) {
    // For a directional light s and uv are affine in p0 (equation 6's denominator is constant), so
    // the vertex shader may compute them per vertex and the rasteriser interpolate: the value at a
    // barycentric mix equals the mix of the values. 1e-5: float rounding of values of order 1.
    ShadowPlane p = zPlane(3.0f);
    p.normal = glm::normalize(glm::vec3(0.2f, 0.3f, 1.0f));
    p.right = glm::normalize(glm::cross(glm::vec3(0, 1, 0), p.normal));
    p.up = glm::cross(p.normal, p.right);
    p.origin = glm::vec3(-1.0f, -1.5f, 0.2f);
    ASSERT_NO_THROW(p.validate("test"));
    const glm::vec3 l = glm::normalize(glm::vec3(0.4f, -0.3f, 0.85f));
    const glm::vec3 a(0.1f, 0.2f, -0.9f), b(1.3f, -0.4f, -0.2f), c(-0.6f, 0.9f, -1.4f);
    const ShadowCoord ca = p.project(a, l), cb = p.project(b, l), cc = p.project(c, l);
    for (const glm::vec3& w : {glm::vec3(0.2f, 0.3f, 0.5f), glm::vec3(0.6f, 0.1f, 0.3f)}) {
        const ShadowCoord mid = p.project(w.x * a + w.y * b + w.z * c, l);
        EXPECT_NEAR(mid.s, w.x * ca.s + w.y * cb.s + w.z * cc.s, 1e-5f);
        EXPECT_NEAR(mid.uv.x, w.x * ca.uv.x + w.y * cb.uv.x + w.z * cc.uv.x, 1e-5f);
        EXPECT_NEAR(mid.uv.y, w.x * ca.uv.y + w.y * cb.uv.y + w.z * cc.uv.y, 1e-5f);
    }
}

TEST(ShadowPlaneTest, SolidOccluderShadowsInsideTheRectangleOnTheLightSideOnly) {
    ShadowPlane p = zPlane(2.0f);
    p.solid = true;
    const glm::vec3 up(0, 0, 1);
    EXPECT_TRUE(p.solidShadows({1.0f, 1.0f, -1.0f}, up));  // under the middle
    EXPECT_FALSE(p.solidShadows({1.0f, 1.0f, 1.0f}, up));  // above: plane behind it
    EXPECT_FALSE(p.solidShadows({2.5f, 1.0f, -1.0f}, up)); // outside the rectangle
    EXPECT_TRUE(p.solidShadows({2.0f, 0.0f, -1.0f}, up));  // on the border: inside, as [0, 1] is
}

TEST(ShadowPlaneTest, ValidateNamesThePlaneAndWhatIsWrong) {
    ShadowPlane p = zPlane(1.0f);
    p.name = "wing";
    p.up = glm::vec3(1, 0, 0);
    try {
        p.validate("scene.json /meshes/0/shadow_planes/1");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("scene.json /meshes/0/shadow_planes/1: shadow plane 'wing'"),
                  std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("perpendicular"), std::string::npos) << e.what();
    }
    p = zPlane(1.0f);
    p.width = 0.0f;
    EXPECT_THROW(p.validate("x"), Error);
    p = zPlane(1.0f);
    p.normal = glm::vec3(0, 0, 2);
    EXPECT_THROW(p.validate("x"), Error);
}

TEST(ShadowPlaneTest, TextureMatrixReproducesTheEquations) {
    // The affine form of equations 6 and 8 for a directional light against project(), at points all
    // around a tilted plane. 1e-5 relative: float rounding of two different evaluation orders.
    ShadowPlane p = zPlane(3.0f);
    p.normal = glm::normalize(glm::vec3(0.2f, 0.3f, 1.0f));
    p.right = glm::normalize(glm::cross(glm::vec3(0, 1, 0), p.normal));
    p.up = glm::cross(p.normal, p.right);
    p.origin = glm::vec3(-1.0f, -1.5f, 0.2f);
    p.height = 2.0f;
    for (const glm::vec3& l :
         {glm::normalize(glm::vec3(0.4f, -0.3f, 0.85f)), glm::normalize(glm::vec3(-1, 0.2f, -0.1f))}) {
        const auto m = p.textureMatrix(l);
        for (const glm::vec3& q :
             {glm::vec3(0.1f, 0.2f, -0.9f), glm::vec3(1.3f, -0.4f, 2.2f), glm::vec3(-3, 1, 0.5f)}) {
            const ShadowCoord c = p.project(q, l);
            const glm::vec4 q1(q, 1.0f);
            const float scale = 1.0f + std::abs(c.s);
            EXPECT_NEAR(glm::dot(m[0], q1), c.uv.x, 1e-5f * scale);
            EXPECT_NEAR(glm::dot(m[1], q1), c.uv.y, 1e-5f * scale);
            EXPECT_NEAR(glm::dot(m[2], q1), c.s, 1e-5f * scale);
        }
    }
}
