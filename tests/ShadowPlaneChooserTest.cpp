// ShadowPlaneChooser (scenes/ShadowPlaneChooser.h) without GL, against closed forms: a square plate
// hovering over a floor (one mesh) casts a shadow whose area is the plate's (a parallel projection of a
// horizontal square onto a horizontal floor keeps its area), so the chooser's ray-cast share of lit
// surface in shadow is known, and its planes must capture most of it with little false shadow; a convex
// box casts no shadow on itself, so it must get no plane and say why.
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "scenes/ShadowPlaneChooser.h"

using namespace sb;

namespace {

/// An n x n grid of quads over [-h, h]^2 at height y, facing up (counter-clockwise seen from above).
void addGrid(Mesh& mesh, const std::string& part, float h, float y, int n) {
    MeshPart p{part, uint32_t(mesh.indices.size()), 0};
    const uint32_t base = uint32_t(mesh.positions.size());
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            mesh.positions.emplace_back(-h + 2.0f * h * float(i) / float(n), y,
                                        -h + 2.0f * h * float(j) / float(n));
            mesh.normals.emplace_back(0.0f, 1.0f, 0.0f);
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const uint32_t a = base + uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n + 1),
                           d = c + 1;
            for (uint32_t v : {a, c, d, a, d, b}) mesh.indices.push_back(v);
        }
    p.indexCount = uint32_t(mesh.indices.size()) - p.firstIndex;
    mesh.parts.push_back(p);
}

/// The closed box [-1, 1]^3, outward wound.
Mesh box() {
    Mesh m;
    m.name = "box";
    for (int i = 0; i < 8; ++i) {
        m.positions.emplace_back((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : -1.0f);
        m.normals.push_back(glm::normalize(m.positions.back()));
    }
    const uint32_t faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                  {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& f : faces)
        for (uint32_t k : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(f[k]);
    return m;
}

} // namespace

TEST(ShadowPlaneChooser, PlateOverFloorGetsAPlaneThatCapturesItsShadow) {
    Mesh mesh;
    mesh.name = "plate_floor";
    addGrid(mesh, "floor", 3.0f, 0.0f, 30);
    addGrid(mesh, "plate", 0.5f, 1.0f, 5);
    const glm::vec3 towardLight = glm::normalize(glm::vec3(-0.3f, 1.0f, -0.2f));
    const ShadowPlaneChoice c = ShadowPlaneChooser::choose(mesh, {towardLight});
    // Lit: the floor (36 m^2) and the plate's top (1 m^2); in shadow: 1 m^2 of floor, 2.7%. The floor is
    // sampled at cell centroids (0.2 m cells, 25 to a square metre), so the shadow's edge cells fall
    // either way: +-0.2 m^2 (20 edge cells of 0.04 m^2, half of them each way), +-0.6 points.
    EXPECT_NEAR(c.shadowedPct, 100.0 / 37.0, 0.6);
    ASSERT_FALSE(c.planes.empty()) << c.reason;
    EXPECT_TRUE(c.reason.empty());
    // The plane the chooser finds (a section just under the plate, or the plate's silhouette across the
    // light) stands for the plate; it may be offset from the plate's height, which shifts its shadow by
    // a few cells: most of the shadow captured, little false.
    EXPECT_GT(c.capturedPct, 0.7 * c.shadowedPct) << c.planes.front().name;
    EXPECT_LT(c.falsePct, 0.2 * c.shadowedPct) << c.planes.front().name;
    for (const ShadowPlane& p : c.planes) EXPECT_NO_THROW(p.validate("test"));
}

TEST(ShadowPlaneChooser, ConvexBoxGetsNoPlaneAndSaysWhy) {
    const ShadowPlaneChoice c =
        ShadowPlaneChooser::choose(box(), {glm::normalize(glm::vec3(0.4f, 1.0f, 0.3f))});
    EXPECT_TRUE(c.planes.empty());
    EXPECT_EQ(c.shadowedPct, 0.0) << "a convex solid shadows no lit point of itself";
    EXPECT_NE(c.reason.find("casts no shadow on itself"), std::string::npos) << c.reason;
    EXPECT_EQ(c.reason.find('\n'), std::string::npos) << "one line";
    // Without light directions the 14 default ones are scored: the same answer.
    EXPECT_TRUE(ShadowPlaneChooser::choose(box(), {}).planes.empty());
}
