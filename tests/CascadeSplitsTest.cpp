// `cascaded`'s split and fitting math against hand-computed numbers and the properties the fit must
// have (techniques/shadowmap/CascadeSplits.h, CascadeFit.h):
//  - the practical split (Zhang et al. 2006, section 3) for lambda 0, 0.5 and 1 and N = 1..4, the
//    values worked out by hand from C_log = n (f/n)^(i/N) and C_uni = n + (f - n) i/N;
//  - near and far read back from the projections glm builds, also with the harness's NDC shift;
//  - texel snapping: the stable fit's origin is a whole multiple of its texel; a camera move smaller
//    than the distance to the next texel boundary leaves the cascade matrix bit-identical, while the
//    tight (unsnapped) fit changes; a move of whole texels moves the snapped origin by whole texels;
//  - the stable extent does not change when the camera turns (the tight box's does), and both boxes
//    hold the slice's 8 corners.
#include <cmath>
#include <cstring>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "techniques/ViewDepth.h"
#include "techniques/shadowmap/CascadeFit.h"
#include "techniques/shadowmap/CascadeSplits.h"

using namespace sb;

namespace {

struct SplitCase {
    float nearZ, farZ;
    int count;
    float lambda;
    std::vector<double> expected; ///< worked out by hand (to 7 digits where irrational)
};

// n = 1, f = 16: the log split is 16^(i/N): 1, 2, 4, 8, 16 for N = 4; 16^(1/3) = 2.5198421,
// 16^(2/3) = 6.3496042. The uniform split steps by 15/N. lambda 0.5 is their mean.
// n = 0.1, f = 1000 (a far plane far beyond the scene): log 0.1, 1, 10, 100, 1000; uniform steps of
// 249.975.
const SplitCase kSplitCases[] = {
    {1, 16, 1, 0.0f, {1, 16}},
    {1, 16, 1, 0.5f, {1, 16}},
    {1, 16, 1, 1.0f, {1, 16}},
    {1, 16, 2, 0.0f, {1, 8.5, 16}},
    {1, 16, 2, 0.5f, {1, 6.25, 16}},
    {1, 16, 2, 1.0f, {1, 4, 16}},
    {1, 16, 3, 0.0f, {1, 6, 11, 16}},
    {1, 16, 3, 0.5f, {1, 4.2599211, 8.6748021, 16}},
    {1, 16, 3, 1.0f, {1, 2.5198421, 6.3496042, 16}},
    {1, 16, 4, 0.0f, {1, 4.75, 8.5, 12.25, 16}},
    {1, 16, 4, 0.5f, {1, 3.375, 6.25, 10.125, 16}},
    {1, 16, 4, 1.0f, {1, 2, 4, 8, 16}},
    {0.1f, 1000, 4, 0.0f, {0.1, 250.075, 500.05, 750.025, 1000}},
    {0.1f, 1000, 4, 0.5f, {0.1, 125.5375, 255.025, 425.0125, 1000}},
    {0.1f, 1000, 4, 1.0f, {0.1, 1, 10, 100, 1000}},
};

TEST(CascadeSplits, PracticalSplitMatchesHandComputedValues) {
    for (const SplitCase& c : kSplitCases) {
        const std::vector<float> s = CascadeSplits::practical(c.nearZ, c.farZ, c.count, c.lambda);
        ASSERT_EQ(s.size(), c.expected.size()) << "N = " << c.count;
        // float results: 2e-7 relative is a few ulps; the hand values are rounded to 8 digits.
        for (size_t i = 0; i < s.size(); ++i)
            EXPECT_NEAR(s[i], c.expected[i], 5e-7 * c.expected[i])
                << "n " << c.nearZ << " f " << c.farZ << " N " << c.count << " lambda " << c.lambda << " i "
                << i;
        EXPECT_EQ(s.front(), c.nearZ); // the ends are exact
        EXPECT_EQ(s.back(), c.farZ);
    }
}

TEST(CascadeSplits, PracticalSplitLiesBetweenUniformAndLog) {
    // For 0 < lambda < 1 each inner split is strictly between the log and the uniform one (the log
    // split is below the uniform one for every inner i when f > n).
    const auto lo = CascadeSplits::practical(0.5f, 300.0f, 4, 1.0f);
    const auto hi = CascadeSplits::practical(0.5f, 300.0f, 4, 0.0f);
    const auto mid = CascadeSplits::practical(0.5f, 300.0f, 4, 0.75f);
    for (size_t i = 1; i + 1 < mid.size(); ++i) {
        EXPECT_LT(lo[i], mid[i]);
        EXPECT_LT(mid[i], hi[i]);
        EXPECT_LT(mid[i - 1], mid[i]);
    }
}

TEST(CascadeSplits, NearFarFromTheProjection) {
    const glm::vec2 p = CascadeSplits::nearFar(glm::perspective(glm::radians(45.0f), 1.5f, 0.25f, 400.0f));
    EXPECT_NEAR(p.x, 0.25f, 1e-5f);
    EXPECT_NEAR(p.y, 400.0f, 400.0f * 1e-4f); // float P[2][2] = -(f+n)/(f-n) loses digits at f/n = 1600
    const glm::vec2 o = CascadeSplits::nearFar(glm::ortho(-3.0f, 3.0f, -2.0f, 2.0f, 1.0f, 50.0f));
    EXPECT_NEAR(o.x, 1.0f, 1e-5f);
    EXPECT_NEAR(o.y, 50.0f, 1e-4f);
    // The harness's sub-pixel shift is a translation in NDC after the projection.
    glm::mat4 shift(1.0f);
    shift[3] = glm::vec4(0.003f, -0.002f, 0.0f, 1.0f);
    const glm::vec2 s =
        CascadeSplits::nearFar(shift * glm::perspective(glm::radians(45.0f), 1.0f, 2.0f, 90.0f));
    EXPECT_NEAR(s.x, 2.0f, 1e-5f);
    EXPECT_NEAR(s.y, 90.0f, 1e-3f);
}

TEST(CascadeSplits, FarClippedToTheReceivers) {
    // Camera at the origin looking down -Z, far 1000; one receiver box spans view depths 8..20.
    const glm::mat4 view = glm::lookAt(glm::vec3(0), glm::vec3(0, 0, -1), glm::vec3(0, 1, 0));
    const glm::mat4 proj = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 1000.0f);
    Aabb box;
    box.extend(glm::vec3(-2, -1, -20));
    box.extend(glm::vec3(2, 1, -8));
    Aabb behind; // wholly behind the camera: not in view, ignored
    behind.extend(glm::vec3(-1, -1, 5));
    behind.extend(glm::vec3(1, 1, 300));
    const glm::vec2 r = CascadeSplits::clipToReceivers({0.1f, 1000.0f}, view, proj, {box, behind});
    const float pad = 0.01f * 12.0f + 1e-5f * 1000.0f; // the documented padding
    EXPECT_NEAR(r.x, 8.0f - pad, 1e-4f);
    EXPECT_NEAR(r.y, 20.0f + pad, 1e-4f);
    // Nothing in view: the camera's own range.
    const glm::vec2 none = CascadeSplits::clipToReceivers({0.1f, 1000.0f}, view, proj, {behind});
    EXPECT_EQ(none, glm::vec2(0.1f, 1000.0f));
}

// --- the fit -------------------------------------------------------------------------------------

constexpr int kResolution = 1024;
const glm::vec3 kLightDir = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));

/// Casters everywhere: the fit is the slice's alone.
CascadeSceneBounds unbounded() {
    CascadeSceneBounds b;
    b.castersMin = glm::vec2(-1e5f);
    b.castersMax = glm::vec2(1e5f);
    b.castersNear = -1e5f;
    b.sceneFar = 1e5f;
    return b;
}

struct Camera {
    glm::vec3 eye, forward;
    glm::mat4 view() const { return glm::lookAt(eye, eye + forward, glm::vec3(0, 1, 0)); }
};

const glm::mat4 kProj = glm::perspective(glm::radians(50.0f), 16.0f / 9.0f, 0.5f, 200.0f);

Cascade fitAt(const Camera& cam, bool stabilize, float d0 = 6.0f, float d1 = 24.0f) {
    return CascadeFit::fit(CascadeFit::lightView(kLightDir), cam.view(), kProj, d0, d1, unbounded(),
                           kResolution, stabilize);
}

bool bitIdentical(const glm::mat4& a, const glm::mat4& b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

/// World-space move that puts the stable fit's unsnapped centre in the middle of its texel cell.
glm::vec3 toCellMiddle(const Cascade& c) {
    const glm::vec3 u = c.unsnappedCentre;
    const glm::vec3 middle = (glm::floor(u / c.texel) + 0.5f) * c.texel;
    return glm::transpose(glm::mat3(c.lightView)) * (middle - u); // light frame -> world (a rotation)
}

TEST(CascadeFit, SnappedOriginIsAWholeMultipleOfTheTexel) {
    for (float x : {0.0f, 1.37f, -52.9f, 1234.567f}) {
        const Cascade c = fitAt({{x, 3.0f + 0.1f * x, 7.0f - x}, {0.2f, -0.3f, -1.0f}}, true);
        ASSERT_GT(c.texel, 0.0f);
        for (int a = 0; a < 3; ++a) {
            const double k = double(c.centre[a]) / double(c.texel);
            EXPECT_NEAR(k, std::round(k), 1e-3) << "axis " << a << " at x " << x;
            // Snapped down, by less than a texel.
            EXPECT_LE(c.centre[a], c.unsnappedCentre[a] + 1e-5f * std::abs(c.unsnappedCentre[a]));
            EXPECT_GT(c.centre[a], c.unsnappedCentre[a] - c.texel);
        }
        // The texel is the box's size over the resolution.
        EXPECT_FLOAT_EQ(c.texel, 2.0f * c.halfExtent / float(kResolution));
    }
}

TEST(CascadeFit, SubTexelCameraMoveLeavesTheStableMatrixBitIdentical) {
    Camera cam{{4.0f, 6.0f, 12.0f}, glm::normalize(glm::vec3(0.1f, -0.35f, -1.0f))};
    cam.eye += toCellMiddle(fitAt(cam, true));
    const Cascade base = fitAt(cam, true), baseTight = fitAt(cam, false);
    const float t = base.texel;
    int tightChanged = 0, moves = 0;
    // Moves of 0.4 texel (the centre stays inside its cell, 0.1 texel from every boundary) in
    // directions along the world axes, along the light and oblique.
    for (const glm::vec3& dir :
         {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1), glm::vec3(-1, 0, 0), kLightDir,
          glm::normalize(glm::vec3(1, 1, -1)), glm::normalize(glm::vec3(-2, 0, 1))}) {
        // Along an oblique direction each light-frame component is at most the move itself.
        Camera moved = cam;
        moved.eye += 0.4f * t * dir;
        const Cascade c = fitAt(moved, true);
        EXPECT_TRUE(bitIdentical(c.viewProj, base.viewProj))
            << "move " << dir.x << "," << dir.y << "," << dir.z;
        EXPECT_NE(c.unsnappedCentre, base.unsnappedCentre); // the camera did move the slice
        tightChanged += !bitIdentical(fitAt(moved, false).viewProj, baseTight.viewProj);
        ++moves;
    }
    // The negative control: the tight box follows the camera, every move changes it.
    EXPECT_EQ(tightChanged, moves);
}

TEST(CascadeFit, WholeTexelMovesMoveTheSnappedOriginByWholeTexels) {
    Camera cam{{-3.0f, 5.0f, 2.0f}, glm::normalize(glm::vec3(-0.4f, -0.2f, -1.0f))};
    cam.eye += toCellMiddle(fitAt(cam, true));
    const Cascade base = fitAt(cam, true);
    // Three texels along the light frame's x axis (its first row) move the origin by exactly 3 texels
    // there and not at all on the other axes.
    const glm::vec3 lightX = glm::transpose(glm::mat3(base.lightView))[0];
    Camera moved = cam;
    moved.eye += 3.0f * base.texel * lightX;
    const Cascade c = fitAt(moved, true);
    EXPECT_NEAR((c.centre.x - base.centre.x) / base.texel, 3.0, 1e-3);
    EXPECT_EQ(c.centre.y, base.centre.y);
    EXPECT_EQ(c.centre.z, base.centre.z);
    EXPECT_EQ(c.halfExtent, base.halfExtent);
}

TEST(CascadeFit, StableExtentIgnoresCameraRotationTightDoesNot) {
    const glm::vec3 eye(2.0f, 8.0f, 5.0f);
    const Cascade a = fitAt({eye, glm::normalize(glm::vec3(0, -0.3f, -1))}, true);
    const Cascade b = fitAt({eye, glm::normalize(glm::vec3(1, -0.6f, 0.4f))}, true);
    EXPECT_EQ(a.halfExtent, b.halfExtent);
    const Cascade ta = fitAt({eye, glm::normalize(glm::vec3(0, -0.3f, -1))}, false);
    const Cascade tb = fitAt({eye, glm::normalize(glm::vec3(1, -0.6f, 0.4f))}, false);
    EXPECT_GT(std::abs(ta.halfExtent - tb.halfExtent), 1e-2f * ta.halfExtent);
}

TEST(CascadeFit, BothBoxesHoldTheSlice) {
    const Camera cam{{1.0f, 7.0f, 9.0f}, glm::normalize(glm::vec3(0.3f, -0.5f, -1.0f))};
    const float d0 = 3.0f, d1 = 17.0f;
    const glm::mat4 invView = glm::inverse(cam.view());
    for (bool stable : {true, false}) {
        const Cascade c = fitAt(cam, stable, d0, d1);
        for (float d : {d0, d1})
            for (const glm::dvec3& p : CascadeFit::viewCorners(kProj, d)) {
                const glm::vec4 world = invView * glm::vec4(glm::vec3(p), 1.0f);
                const glm::vec4 clip = c.viewProj * world;
                EXPECT_LE(std::abs(clip.x), 1.0f + 1e-5f) << (stable ? "stable" : "tight");
                EXPECT_LE(std::abs(clip.y), 1.0f + 1e-5f) << (stable ? "stable" : "tight");
                EXPECT_LE(std::abs(clip.z), 1.0f + 1e-5f) << (stable ? "stable" : "tight");
            }
        // The corners really lie at those view depths.
        for (const glm::dvec3& p : CascadeFit::viewCorners(kProj, d1)) EXPECT_NEAR(-p.z, d1, 1e-9);
    }
}

TEST(CascadeFit, SphereOfASymmetricSliceMatchesTheClosedForm) {
    // Symmetric frustum: tan(fov/2) = a, aspect r; the corner at depth d is d * (r a, a) off the axis,
    // k^2 = a^2 (1 + r^2). Equidistant centre on the axis: z = (d0 + d1)(1 + k^2) / 2, clamped to d1.
    const float fov = glm::radians(50.0f), aspect = 16.0f / 9.0f;
    const double a = std::tan(0.5 * double(fov)), k2 = a * a * (1.0 + double(aspect) * aspect);
    for (auto [d0, d1] : {std::pair{6.0, 24.0}, std::pair{20.0, 21.0}, std::pair{0.5, 200.0}}) {
        const glm::dvec4 s = CascadeFit::sliceSphere(kProj, float(d0), float(d1));
        const double z = std::min((d0 + d1) * (1.0 + k2) / 2.0, d1);
        const double r = std::max(std::sqrt((z - d0) * (z - d0) + d0 * d0 * k2),
                                  std::sqrt((d1 - z) * (d1 - z) + d1 * d1 * k2));
        EXPECT_NEAR(-s.z, z, 1e-6 * d1) << d0 << ".." << d1;
        EXPECT_NEAR(s.w, r, 1e-6 * d1) << d0 << ".." << d1;
        EXPECT_NEAR(s.x, 0.0, 1e-9);
        EXPECT_NEAR(s.y, 0.0, 1e-9);
    }
}

TEST(CascadeFit, CastersBoundsClampTheStableBox) {
    // Casters only in a 4 x 4 light-frame square far smaller than the slice: the box takes their size
    // and holds them whole, the same box wherever the camera is (both are scene constants).
    CascadeSceneBounds b = unbounded();
    b.castersMin = glm::vec2(-2.0f, 1.0f);
    b.castersMax = glm::vec2(2.0f, 5.0f);
    const glm::mat4 light = CascadeFit::lightView(kLightDir);
    const Cascade a =
        CascadeFit::fit(light, Camera{{0, 5, 30}, {0, 0, -1}}.view(), kProj, 6, 60, b, kResolution, true);
    const Cascade c =
        CascadeFit::fit(light, Camera{{1, 5, 29}, {0, 0, -1}}.view(), kProj, 6, 60, b, kResolution, true);
    EXPECT_NEAR(a.halfExtent, 2.0f * kResolution / (kResolution - 2), 1e-4f);
    const glm::mat4 ortho = a.viewProj * glm::inverse(light); // light frame -> clip
    for (glm::vec2 corner : {b.castersMin, b.castersMax, glm::vec2(b.castersMin.x, b.castersMax.y)}) {
        const glm::vec4 clip = ortho * glm::vec4(corner, -10.0f, 1.0f);
        EXPECT_LE(std::abs(clip.x), 1.0f);
        EXPECT_LE(std::abs(clip.y), 1.0f);
    }
    EXPECT_EQ(a.centre.x, c.centre.x);
    EXPECT_EQ(a.centre.y, c.centre.y);
}

TEST(CascadeFit, RadiusRoundsUpByAtMostOneThirtySecond) {
    for (double r : {0.013, 0.51, 1.07, 7.3, 1000.1}) {
        const double q = CascadeFit::roundRadius(r);
        EXPECT_GE(q, r);
        EXPECT_LE(q, r * (1.0 + 1.0 / 32.0) + 1e-12);
        EXPECT_EQ(CascadeFit::roundRadius(r * (1.0 + 1e-9)), q)
            << "a slightly different radius keeps the size";
    }
}

} // namespace

// fit=sdsm: the window depths the reduction returns back to view depth (techniques/ViewDepth.h, the view
// depth pre-pass's neutral half; here beside the splits it feeds, not in an executable of its own). The
// closed form of GL's perspective window depth, w(d) = f (d - n) / (d (f - n)), is the independent answer;
// orthographic is linear, w(d) = (d - n) / (f - n). 1e-4 relative: float projection entries (as
// NearFarFromTheProjection) and the float window depth, whose ulp near 1 is worth 6e-4 of view depth at d = f
// = 100.
TEST(ViewDepth, ViewDepthsInvertTheWindowDepth) {
    const float n = 1.0f, f = 100.0f;
    const glm::mat4 persp = glm::perspective(glm::radians(50.0f), 1.25f, n, f);
    const glm::mat4 ortho = glm::ortho(-4.0f, 4.0f, -3.0f, 3.0f, n, f);
    for (double d : {1.0, 4.0, 25.0, 100.0}) {
        const float wp = float(f * (d - n) / (d * (f - n))), wo = float((d - n) / (f - n));
        const glm::vec2 p = ViewDepth::viewDepths({wp, wp}, persp);
        const glm::vec2 o = ViewDepth::viewDepths({wo, wo}, ortho);
        EXPECT_NEAR(p.x, d, 1e-4 * d) << "perspective, depth " << d;
        EXPECT_NEAR(o.y, d, 1e-4 * d) << "orthographic, depth " << d;
    }
}

// The sample distribution split of a known interval: samples [2, 32] within [0.1, 1000], padded by
// 1% of 30 plus 1e-5 of 1000 = 0.31 to [1.69, 32.31], then C_i = 1.69 (32.31 / 1.69)^(i / 4), worked out
// to 8 digits: 1.69, 3.5338594, 7.3894452, 15.451633, 32.31. No sample (min > max): the log split of
// the camera's [0.1, 1000], 10^(i - 1).
TEST(CascadeSplits, SampleDistributionSplitsTheSampledInterval) {
    const std::vector<float> s = CascadeSplits::sampleDistribution({2.0f, 32.0f}, {0.1f, 1000.0f}, 4);
    const double expected[] = {1.69, 3.5338594, 7.3894452, 15.4516334, 32.31};
    ASSERT_EQ(s.size(), 5u);
    // float arithmetic of the padding and the power: a few ulps, 1e-6 relative.
    for (size_t i = 0; i < s.size(); ++i) EXPECT_NEAR(s[i], expected[i], 1e-6 * expected[i]) << "i " << i;
    const std::vector<float> none = CascadeSplits::sampleDistribution({1.0f, 0.0f}, {0.1f, 1000.0f}, 4);
    const double log10[] = {0.1, 1, 10, 100, 1000};
    ASSERT_EQ(none.size(), 5u);
    for (size_t i = 0; i < none.size(); ++i) EXPECT_NEAR(none[i], log10[i], 5e-7 * log10[i]) << "i " << i;
    // A sampled interval beyond the camera's is clamped to it.
    const std::vector<float> wide = CascadeSplits::sampleDistribution({0.05f, 2000.0f}, {0.1f, 1000.0f}, 2);
    EXPECT_EQ(wide.front(), 0.1f);
    EXPECT_EQ(wide.back(), 1000.0f);
}
