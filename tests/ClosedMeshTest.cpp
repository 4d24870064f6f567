// Unit tests of scenes/ClosedMesh: hand-built meshes whose closedness follows from their construction
// (a tetrahedron, the same with a face removed or every winding flipped, two cubes, a cube with split
// vertices per face), and the built-in generators, each with the verdict their geometry implies.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/Paths.h"
#include "scenes/ClosedMesh.h"
#include "scenes/MeshGenerators.h"

using namespace sb;

namespace {

/// A tetrahedron with counter-clockwise (outward) faces seen from outside.
Mesh tetrahedron() {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    m.normals.assign(4, glm::vec3(0, 0, 1));
    m.indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    return m;
}

void flipWindings(Mesh& m) {
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3) std::swap(m.indices[t + 1], m.indices[t + 2]);
}

/// An axis-aligned cube with 24 vertices (4 per face, none shared between faces), outward winding.
Mesh splitCube(glm::vec3 centre, float half) {
    Mesh m;
    for (int axis = 0; axis < 3; ++axis)
        for (int sign = -1; sign <= 1; sign += 2) {
            glm::vec3 n(0.0f);
            n[axis] = float(sign);
            glm::vec3 u(0.0f), v(0.0f);
            u[(axis + 1) % 3] = 1.0f;
            v[(axis + 2) % 3] = 1.0f;
            if (sign < 0) std::swap(u, v); // keep u x v along n
            const uint32_t base = uint32_t(m.positions.size());
            for (glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
                m.positions.push_back(centre + half * (n + c.x * u + c.y * v));
                m.normals.push_back(n);
            }
            for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
        }
    return m;
}

Mesh join(const Mesh& a, const Mesh& b) {
    Mesh m = a;
    const uint32_t base = uint32_t(m.positions.size());
    m.positions.insert(m.positions.end(), b.positions.begin(), b.positions.end());
    m.normals.insert(m.normals.end(), b.normals.begin(), b.normals.end());
    for (uint32_t i : b.indices) m.indices.push_back(base + i);
    return m;
}

} // namespace

TEST(ClosedMesh, TetrahedronIsClosed) {
    const ClosedMeshReport r = computeClosedness(tetrahedron());
    EXPECT_EQ(r.unmatchedEdges, 0u);
    EXPECT_EQ(r.components, 1u);
    EXPECT_EQ(r.inwardComponents, 0u);
    EXPECT_TRUE(r.closed());
}

TEST(ClosedMesh, RemovingOneFaceOpensIt) {
    Mesh m = tetrahedron();
    m.indices.resize(9);
    const ClosedMeshReport r = computeClosedness(m);
    EXPECT_EQ(r.unmatchedEdges, 3u); // the missing face's three edges
    EXPECT_FALSE(r.closed());
}

TEST(ClosedMesh, FlippedWindingsAreInsideOut) {
    Mesh m = tetrahedron();
    flipWindings(m);
    const ClosedMeshReport r = computeClosedness(m);
    EXPECT_EQ(r.unmatchedEdges, 0u); // still an oriented surface without boundary
    EXPECT_EQ(r.inwardComponents, 1u);
    EXPECT_FALSE(r.closed());
}

TEST(ClosedMesh, SplitVerticesWeldIntoOneClosedCube) {
    const Mesh cube = splitCube({0, 0, 0}, 1.0f);
    ASSERT_EQ(cube.positions.size(), 24u);
    EXPECT_TRUE(isClosedMesh(cube));
}

TEST(ClosedMesh, TwoDisjointCubesAreClosed) {
    const ClosedMeshReport r =
        computeClosedness(join(splitCube({0, 0, 0}, 1.0f), splitCube({5, 0, 0}, 0.5f)));
    EXPECT_EQ(r.components, 2u);
    EXPECT_TRUE(r.closed());
}

TEST(ClosedMesh, OneInsideOutComponentMakesItNotClosed) {
    Mesh inward = splitCube({5, 0, 0}, 0.5f);
    flipWindings(inward);
    const ClosedMeshReport r = computeClosedness(join(splitCube({0, 0, 0}, 1.0f), inward));
    EXPECT_EQ(r.components, 2u);
    EXPECT_EQ(r.inwardComponents, 1u);
    EXPECT_FALSE(r.closed());
}

TEST(ClosedMesh, EmptyMeshIsNotClosed) {
    EXPECT_FALSE(isClosedMesh(Mesh{}));
}

// The generators' verdicts: the solids are closed (the sphere's and the fuselage's poles weld only with
// -0 taken as +0), the plane and the teapot are not (the Bezier patches meet at positions that differ
// in their last bits, 128 open directed edges at tessellation 8). A verdict that changes means the
// generator's topology changed, and with it what --back-faces cull may drop.
TEST(ClosedMesh, BuiltInGenerators) {
    EXPECT_TRUE(isClosedMesh(MeshGenerators::sphere(16)));
    EXPECT_TRUE(isClosedMesh(MeshGenerators::box(glm::vec3(1.0f), 1)));
    EXPECT_TRUE(isClosedMesh(MeshGenerators::box(glm::vec3(1, 2, 3), 4)));
    EXPECT_TRUE(isClosedMesh(MeshGenerators::cylinder(16)));
    EXPECT_TRUE(isClosedMesh(MeshGenerators::aircraft(16)));
    EXPECT_TRUE(isClosedMesh(MeshGenerators::lantern(0.08f, 16)));
    const ClosedMeshReport plane = computeClosedness(MeshGenerators::plane(10.0f, 4));
    EXPECT_EQ(plane.unmatchedEdges, 16u); // the border: 4 sides of 4 quads
    EXPECT_FALSE(plane.closed());
    const std::string teapot = Paths::findResource("scenes/data/teapot.bpt");
    ASSERT_FALSE(teapot.empty()) << "scenes/data/teapot.bpt not found";
    const ClosedMeshReport r = computeClosedness(MeshGenerators::teapot(teapot, 8));
    EXPECT_EQ(r.unmatchedEdges, 128u);
    EXPECT_FALSE(r.closed());
}
