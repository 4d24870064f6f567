// reference/VulkanGBufferRenderer.h against what the Vulkan lighting pass itself rasterised, as
// tests/GBufferGLTest.cpp checks the GL renderer: on sphere_plane seen from the top camera, in both Vulkan
// submission modes, the G-buffer covers exactly the pixels of `none`'s lit pass (its depth buffer), its
// positions are the depth-unprojected world positions, its object ids name the instance under the
// pixel and its primitive ids a triangle of that instance's mesh containing the position (PrimitiveId
// restarts per draw and per instance of an instanced draw). The harness's own hook
// (MeasuredHarness::renderGBuffer) is what is tested: the accuracy evaluator's samples on Vulkan. And the
// validation layer reports nothing.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "VulkanFrame.h"
#include "reference/GBuffer.h"
#include "scenes/Math.h"

using namespace sb;

namespace {

constexpr int kSize = 128;
constexpr int kTessellation = 48;

/// Distance from p to the triangle (a, b, c), by projection onto its plane and its edges.
double pointTriangleDistance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                             const glm::dvec3& c) {
    const glm::dvec3 n = glm::normalize(glm::cross(b - a, c - a));
    const glm::dvec3 q = p - n * glm::dot(p - a, n);
    const bool inside = glm::dot(glm::cross(b - a, q - a), n) >= 0 &&
                        glm::dot(glm::cross(c - b, q - b), n) >= 0 &&
                        glm::dot(glm::cross(a - c, q - c), n) >= 0;
    if (inside) return std::abs(glm::dot(p - a, n));
    auto segment = [&](const glm::dvec3& u, const glm::dvec3& v) {
        const double t = std::clamp(glm::dot(p - u, v - u) / glm::dot(v - u, v - u), 0.0, 1.0);
        return glm::length(p - (u + t * (v - u)));
    };
    return std::min({segment(a, b), segment(b, c), segment(c, a)});
}

/// World-space extent of pixel i on its surface: the largest distance to a covered 4-neighbour of the
/// same instance (0 without one).
double surfaceFootprint(const GBuffer& g, size_t i) {
    const int x = int(i % size_t(g.width)), y = int(i / size_t(g.width));
    const int offsets[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    double out = 0.0;
    for (const auto& o : offsets) {
        const int nx = x + o[0], ny = y + o[1];
        if (nx < 0 || ny < 0 || nx >= g.width || ny >= g.height) continue;
        const size_t n = size_t(ny) * size_t(g.width) + size_t(nx);
        if (!g.covered(n) || g.instance(n) != g.instance(i)) continue;
        out = std::max(out, double(glm::length(glm::vec3(g.position[n]) - glm::vec3(g.position[i]))));
    }
    return out;
}

class GBufferVulkanModes : public ::testing::TestWithParam<SubmitMode> {};

TEST_P(GBufferVulkanModes, MatchesTheLightingPass) {
    RunConfig cfg = test::quickConfig("sphere_plane", "top", kSize, GetParam());
    cfg.sceneOptions.tessellation = kTessellation;
    test::VulkanFrame frame(cfg, "none");
    VulkanHarness& h = frame.harness();
    const Scene& scene = h.scene();
    const CameraPreset& cam = h.camera();
    const glm::mat4 viewProj = cameraProjection(cam, 1.0f) * cameraView(cam);
    // Window depth is GL's on Vulkan too (VulkanFrameBlock::clipFromGl), rows bottom-up.
    const std::vector<glm::vec4> world =
        test::unprojectDepth(h.targets().readDepth(), kSize, kSize, viewProj);
    h.renderGBuffer(); // twice: the second render must clear what the first left
    const GBuffer g = h.renderGBuffer();
    ASSERT_EQ(g.width, kSize);
    ASSERT_EQ(g.height, kSize);
    ASSERT_EQ(g.backFacing.size(), g.size());

    uint32_t groundIndex = 0, sphereIndex = 0;
    for (uint32_t i = 0; i < scene.instances.size(); ++i)
        (scene.instances[i].castsShadow ? sphereIndex : groundIndex) = i;
    const double snapStep = std::ldexp(1.0, -int(h.context().properties().limits.subPixelPrecisionBits));
    int covered = 0, coverageMismatch = 0, positionWrong = 0, idWrong = 0, primitiveWrong = 0, background = 0;
    int groundPixels = 0, spherePixels = 0;
    double worstPosition = 0.0;
    for (size_t i = 0; i < g.size(); ++i) {
        const bool inDepth = world[i].w != 0.0f;
        if (inDepth != g.covered(i)) {
            ++coverageMismatch;
            continue;
        }
        if (!inDepth) {
            ++background;
            EXPECT_EQ(g.primitive[i], 0u);
            continue;
        }
        ++covered;
        const glm::dvec3 p(g.position[i]);
        // Depth quantisation (24 bits, two steps) at the sample's distance, plus float slack.
        const double z = glm::length(glm::dvec3(world[i]) - glm::dvec3(cam.eye));
        const double step = z * z * (cam.farZ - cam.nearZ) / (cam.farZ * cam.nearZ) / double((1u << 24) - 1u);
        const double dp = glm::length(p - glm::dvec3(world[i]));
        worstPosition = std::max(worstPosition, dp);
        if (dp > 2.0 * step + 1e-4 && ++positionWrong <= 5)
            ADD_FAILURE() << "pixel " << i << ": G-buffer " << p.x << "," << p.y << "," << p.z << " depth "
                          << world[i].x << "," << world[i].y << "," << world[i].z;
        // The ground is the plane y = 0, the sphere stands above it; the top camera sees front faces.
        const uint32_t expected = std::abs(p.y) < 1e-3 ? groundIndex : sphereIndex;
        (expected == groundIndex ? groundPixels : spherePixels) += 1;
        if (g.instance(i) != expected && ++idWrong <= 5)
            ADD_FAILURE() << "pixel " << i << ": instance " << g.instance(i) << ", expected " << expected;
        EXPECT_EQ(g.backFacing[i], 0) << "pixel " << i;
        if (g.instance(i) >= scene.instances.size()) continue;
        const Instance& inst = scene.instances[g.instance(i)];
        const Mesh& mesh = scene.meshes[inst.mesh];
        const uint32_t prim = g.primitive[i];
        if (prim >= mesh.triangleCount()) {
            if (++primitiveWrong <= 5)
                ADD_FAILURE() << "pixel " << i << ": primitive " << prim << " out of range";
            continue;
        }
        glm::dvec3 v[3];
        for (int k = 0; k < 3; ++k)
            v[k] = glm::dvec3(inst.model *
                              glm::vec4(mesh.positions[mesh.indices[3 * prim + uint32_t(k)]], 1.0f));
        // Coverage is decided on snapped vertices, attributes interpolated from exact ones: one snap step
        // of the pixel's footprint, plus float slack (tests/GBufferGLTest.cpp says more).
        const double d = pointTriangleDistance(p, v[0], v[1], v[2]);
        if (d > surfaceFootprint(g, i) * snapStep + 1e-5 && ++primitiveWrong <= 5)
            ADD_FAILURE() << "pixel " << i << ": primitive " << prim << " is " << d
                          << " away from the sample";
    }
    EXPECT_EQ(coverageMismatch, 0) << "the G-buffer must cover exactly the lighting pass's pixels";
    EXPECT_GT(covered, kSize * kSize / 2);
    EXPECT_GT(spherePixels, 200);
    EXPECT_GT(groundPixels, 2000);
    EXPECT_EQ(positionWrong, 0) << "worst " << worstPosition;
    EXPECT_EQ(idWrong, 0);
    EXPECT_EQ(primitiveWrong, 0);
}

INSTANTIATE_TEST_SUITE_P(GBuffer, GBufferVulkanModes,
                         ::testing::Values(SubmitMode::Retained, SubmitMode::Instanced),
                         [](const auto& p) { return std::string(submitModeName(p.param)); });

} // namespace
