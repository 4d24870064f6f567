// GBufferRenderer against what the lighting pass itself rasterised: on sphere_plane seen from the top
// camera, the G-buffer's coverage is the depth buffer's, its positions are the depth-unprojected world
// positions, its object ids name the instance under the pixel and its primitive ids name a triangle
// of that instance's mesh that contains the position, in each of the four submission modes (the
// primitive id must restart per draw and per instance of an instanced draw, and glBegin/glEnd streams
// must not be split into several primitives by the driver).
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/harness/Harness.h"
#include "core/Error.h"
#include "reference/GBufferRenderer.h"
#include "scenes/Math.h"
#include "techniques/none/NoneGL.h"

using namespace sb;

namespace {

constexpr int kSize = 256;
// Fine enough that one glBegin/glEnd stream (65536 triangles, 196608 vertices) overflows any
// immediate-mode vertex buffer a driver keeps: a driver that splits the stream would restart
// gl_PrimitiveID mid-mesh and fail the primitive check.
constexpr int kTessellation = 128;

/// Distance from p to the triangle (a, b, c) (Ericson, Real-Time Collision Detection, 5.1.5).
double pointTriangleDistance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                             const glm::dvec3& c) {
    glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return glm::length(p - a);
    glm::dvec3 bp = p - b;
    double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return glm::length(p - b);
    double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return glm::length(p - (a + ab * (d1 / (d1 - d3))));
    glm::dvec3 cp = p - c;
    double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return glm::length(p - c);
    double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return glm::length(p - (a + ac * (d2 / (d2 - d6))));
    double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
        return glm::length(p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)))));
    double denom = 1.0 / (va + vb + vc);
    return glm::length(p - (a + ab * (vb * denom) + ac * (vc * denom)));
}

/// World-space distance that one step of a 24-bit depth buffer spans at eye distance z for a
/// perspective projection with planes n, f: z_window = f(z - n) / (z(f - n)), so
/// dz/dz_window = z^2 (f - n) / (f n).
double depthStepWorld(double z, const CameraPreset& cam) {
    double n = cam.nearZ, f = cam.farZ;
    return z * z * (f - n) / (f * n) / double((1u << 24) - 1u);
}

/// World distance from sample i to its farthest covered 4-neighbour on the same instance: the extent
/// of the pixel on that surface (0 when it has no such neighbour).
double surfaceFootprint(const GBuffer& g, size_t i) {
    const int x = int(i % size_t(g.width)), y = int(i / size_t(g.width));
    const int offsets[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    double out = 0.0;
    for (const auto& o : offsets) {
        int nx = x + o[0], ny = y + o[1];
        if (nx < 0 || ny < 0 || nx >= g.width || ny >= g.height) continue;
        size_t n = size_t(ny) * size_t(g.width) + size_t(nx);
        if (!g.covered(n) || g.instance(n) != g.instance(i)) continue;
        out = std::max(out, double(glm::length(glm::vec3(g.position[n]) - glm::vec3(g.position[i]))));
    }
    return out;
}

class GBufferModes : public ::testing::TestWithParam<SubmitMode> {};

TEST_P(GBufferModes, MatchesTheLightingPass) {
    RunConfig cfg = test::quickConfig("sphere_plane", "top", kSize, GetParam());
    cfg.sceneOptions.tessellation = kTessellation;
    Harness h(cfg);
    NoneGL none;
    h.prepare(none);
    h.renderFrame(none);
    const Scene& scene = h.scene();
    const CameraPreset& cam = h.camera();
    glm::mat4 viewProj = cameraProjection(cam, 1.0f) * cameraView(cam);
    auto depth = h.targets().readDepth();
    auto world = test::unprojectDepth(depth, kSize, kSize, viewProj);

    GBufferRenderer renderer(kSize, kSize);
    renderer.setScene(scene);
    GBuffer g = renderer.render(h.submitter(), h.programs(), viewProj);
    ASSERT_EQ(g.width, kSize);
    ASSERT_EQ(g.height, kSize);
    ASSERT_EQ(g.size(), world.size());
    // Same rasterisation: the G-buffer's depth buffer equals the lighting pass's, bit for bit.
    std::vector<float> gbufferDepth(size_t(kSize) * kSize);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, renderer.fbo());
    glReadPixels(0, 0, kSize, kSize, GL_DEPTH_COMPONENT, GL_FLOAT, gbufferDepth.data());
    size_t depthDiffers = 0;
    for (size_t i = 0; i < depth.size(); ++i) depthDiffers += gbufferDepth[i] != depth[i];
    EXPECT_EQ(depthDiffers, 0u) << "pixels whose G-buffer depth differs from the lighting pass's";
    // State is restored: the harness's targets are still the bound draw framebuffer.
    GLint drawFbo = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFbo);
    EXPECT_EQ(GLuint(drawFbo), h.targets().fbo());

    uint32_t groundIndex = 0, sphereIndex = 0;
    for (uint32_t i = 0; i < scene.instances.size(); ++i)
        (scene.instances[i].castsShadow ? sphereIndex : groundIndex) = i;

    GLint subpixelBits = 0;
    glGetIntegerv(GL_SUBPIXEL_BITS, &subpixelBits);
    ASSERT_GT(subpixelBits, 0);
    const double snapStep = std::ldexp(1.0, -subpixelBits);
    int covered = 0, coverageMismatch = 0, positionWrong = 0, idWrong = 0, primitiveWrong = 0;
    int groundPixels = 0, spherePixels = 0;
    double worstPosition = 0.0, worstPrimitive = 0.0;
    for (size_t i = 0; i < g.size(); ++i) {
        bool inDepth = world[i].w != 0.0f;
        if (inDepth != g.covered(i)) {
            ++coverageMismatch;
            continue;
        }
        if (!inDepth) continue;
        ++covered;
        glm::dvec3 p(g.position[i]);
        // Position: depth24 quantisation (rounding to a step, one step allowed for either rounding
        // direction, doubled for slack) dominates; float interpolation and the float inverse matrix add
        // relative errors of ~1e-6 of |p| (< 1e-4 at |p| <= 30), covered by the absolute floor.
        double z = glm::length(glm::dvec3(world[i]) - glm::dvec3(cam.eye));
        double positionTol = 2.0 * depthStepWorld(z, cam) + 1e-4;
        double dp = glm::length(p - glm::dvec3(world[i]));
        worstPosition = std::max(worstPosition, dp);
        if (dp > positionTol && ++positionWrong <= 5)
            ADD_FAILURE() << "pixel " << i << ": G-buffer " << p.x << "," << p.y << "," << p.z << " depth "
                          << world[i].x << "," << world[i].y << "," << world[i].z << " (tolerance "
                          << positionTol << ")";
        // Object id: the ground is the plane y = 0, the sphere is above y = 2.
        uint32_t expected = std::abs(p.y) < 1e-3 ? groundIndex : sphereIndex;
        (expected == groundIndex ? groundPixels : spherePixels) += 1;
        if (g.instance(i) != expected && ++idWrong <= 5)
            ADD_FAILURE() << "pixel " << i << " at y " << p.y << ": instance " << g.instance(i)
                          << ", expected " << expected;
        if (g.instance(i) >= scene.instances.size()) continue;
        // Primitive: the triangle of that instance's mesh, transformed by its model matrix as the
        // vertex shader does, must contain the interpolated position. The rasteriser decides coverage
        // with vertices snapped to 2^-subpixelBits of a pixel while attributes are interpolated from
        // the exact ones, so a covered pixel centre may lie up to one snap step (in screen space)
        // outside the exact triangle: one snap step of the pixel's surface footprint (the largest
        // distance to a neighbouring sample on the same instance), plus 1e-5 for float interpolation.
        const Instance& inst = scene.instances[g.instance(i)];
        const Mesh& mesh = scene.meshes[inst.mesh];
        uint32_t prim = g.primitive[i];
        if (prim >= mesh.triangleCount()) {
            if (++primitiveWrong <= 5)
                ADD_FAILURE() << "pixel " << i << ": primitive " << prim << " out of range";
            continue;
        }
        glm::dvec3 v[3];
        for (int k = 0; k < 3; ++k)
            v[k] = glm::dvec3(inst.model *
                              glm::vec4(mesh.positions[mesh.indices[3 * prim + uint32_t(k)]], 1.0f));
        double d = pointTriangleDistance(p, v[0], v[1], v[2]);
        double primitiveTol = surfaceFootprint(g, i) * snapStep + 1e-5;
        worstPrimitive = std::max(worstPrimitive, d / primitiveTol);
        if (d > primitiveTol && ++primitiveWrong <= 5)
            ADD_FAILURE() << "pixel " << i << ": primitive " << prim << " of instance " << g.instance(i)
                          << " is " << d << " away from the sample (tolerance " << primitiveTol << ")";
    }
    EXPECT_EQ(coverageMismatch, 0) << "the G-buffer must cover exactly the lighting pass's pixels";
    EXPECT_GT(covered, kSize * kSize / 2);
    EXPECT_GT(spherePixels, 1000);
    EXPECT_GT(groundPixels, 10000);
    EXPECT_EQ(positionWrong, 0) << "worst " << worstPosition;
    EXPECT_EQ(idWrong, 0);
    EXPECT_EQ(primitiveWrong, 0) << "worst distance / tolerance " << worstPrimitive;
    RecordProperty("worst_position_error", std::to_string(worstPosition));
    RecordProperty("worst_primitive_distance_over_tolerance", std::to_string(worstPrimitive));
}

INSTANTIATE_TEST_SUITE_P(GBuffer, GBufferModes, ::testing::ValuesIn(kAllSubmitModes),
                         [](const auto& p) { return std::string(submitModeName(p.param)); });

TEST(GBufferRenderer, BackgroundIsCleared) {
    // The side camera sees sky above the horizon: those pixels must read object id 0 and primitive 0,
    // also on a second render (the clear happens every time).
    Harness h(test::quickConfig("sphere_plane", "far", 64));
    glm::mat4 viewProj = cameraProjection(h.camera(), 1.0f) * cameraView(h.camera());
    GBufferRenderer renderer(64, 64);
    renderer.render(h.submitter(), h.programs(), viewProj);
    GBuffer g = renderer.render(h.submitter(), h.programs(), viewProj);
    int background = 0;
    for (size_t i = 0; i < g.size(); ++i) {
        if (g.covered(i)) continue;
        ++background;
        EXPECT_EQ(g.position[i], glm::vec4(0.0f));
        EXPECT_EQ(g.primitive[i], 0u);
    }
    EXPECT_GT(background, 0);
    EXPECT_LT(background, int(g.size()));
}

} // namespace

namespace {

TEST(GBufferRenderer, ImmediateSubmissionWithoutSceneIsAnError) {
    // Without the scene the renderer could only use the submitter's glBegin/glEnd streams, whose
    // primitive ids are wrong beyond the first few thousand triangles: refuse rather than mislabel.
    Harness h(test::quickConfig("sphere_plane", "top", 32, SubmitMode::Immediate));
    glm::mat4 viewProj = cameraProjection(h.camera(), 1.0f) * cameraView(h.camera());
    GBufferRenderer renderer(32, 32);
    try {
        renderer.render(h.submitter(), h.programs(), viewProj);
        FAIL() << "rendered without a scene";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("setScene"), std::string::npos) << e.what();
    }
}

} // namespace
