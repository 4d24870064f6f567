// ReceiverSections (techniques/occluder/ReceiverSections.h) without GL: the per-vertex masks of the
// planes each vertex receives, counted by hand for a two-part mesh, and the hash table's lookup of every
// vertex of a larger mesh (what shaders/occluder/scene.vert mirrors).
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "core/Error.h"
#include "techniques/occluder/ReceiverSections.h"

using namespace sb;

namespace {

ShadowPlane planeReceiving(const std::string& name, std::vector<std::string> receivers) {
    ShadowPlane p;
    p.name = name;
    p.receivers = std::move(receivers);
    return p;
}

} // namespace

TEST(ReceiverSections, MasksFollowThePartsAndSeamsTakeTheirAnd) {
    // Part "a": triangle 0-1-2, part "b": triangle 2-3-4 (vertex 2 on the seam). Plane 0 shadows "a",
    // plane 1 every part, plane 2 "b".
    Mesh mesh;
    mesh.name = "two";
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 1, 0}, {0, 2, 0}};
    mesh.indices = {0, 1, 2, 2, 3, 4};
    mesh.parts = {{"a", 0, 3}, {"b", 3, 3}};
    const std::vector<ShadowPlane> planes = {planeReceiving("p0", {"a"}), planeReceiving("p1", {}),
                                             planeReceiving("p2", {"b"})};
    ASSERT_TRUE(ReceiverSections::needed(planes));
    EXPECT_FALSE(ReceiverSections::needed({planeReceiving("p", {})}));
    const std::vector<glm::uvec4> table = ReceiverSections::build(mesh, planes);
    EXPECT_EQ(ReceiverSections::lookup(table, mesh.positions[0]), 0b011u); // a: p0 and p1
    EXPECT_EQ(ReceiverSections::lookup(table, mesh.positions[1]), 0b011u);
    EXPECT_EQ(ReceiverSections::lookup(table, mesh.positions[2]), 0b010u); // seam: a AND b = p1
    EXPECT_EQ(ReceiverSections::lookup(table, mesh.positions[3]), 0b110u); // b: p1 and p2
    EXPECT_EQ(ReceiverSections::lookup(table, glm::vec3(5, 5, 5)), ReceiverSections::kAll) << "not a vertex";
    EXPECT_THROW(ReceiverSections::build(mesh, {planeReceiving("p", {"c"})}), Error) << "unknown part";
}

TEST(ReceiverSections, EveryVertexOfALargerMeshIsFound) {
    // 40 x 40 vertices in two parts split at the middle row, the table at most half full: each vertex's
    // lookup returns its part's mask (plane 0 receives the lower half), the middle row the AND (none).
    Mesh mesh;
    mesh.name = "grid";
    constexpr int n = 40;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            mesh.positions.emplace_back(0.37f * float(i), -1.3f * float(j), 1e-3f * float(i * j));
    for (int half = 0; half < 2; ++half) {
        MeshPart part{half == 0 ? "lower" : "upper", uint32_t(mesh.indices.size()), 0};
        for (int j = half * (n / 2 - 1); j < (half == 0 ? n / 2 - 1 : n - 1); ++j)
            for (int i = 0; i + 1 < n; ++i) {
                const uint32_t a = uint32_t(j * n + i), b = a + 1, c = a + uint32_t(n), d = c + 1;
                for (uint32_t v : {a, b, d, a, d, c}) mesh.indices.push_back(v);
            }
        part.indexCount = uint32_t(mesh.indices.size()) - part.firstIndex;
        mesh.parts.push_back(part);
    }
    const std::vector<glm::uvec4> table = ReceiverSections::build(mesh, {planeReceiving("p", {"lower"})});
    EXPECT_GE(table.size(), 2 * mesh.positions.size());
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const uint32_t expected = j < n / 2 - 1 ? 1u : 0u; // row n/2 - 1 is shared: lower AND upper
            EXPECT_EQ(ReceiverSections::lookup(table, mesh.positions[size_t(j * n + i)]), expected)
                << "vertex " << i << ", " << j;
        }
}
