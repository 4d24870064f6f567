// Unit tests of techniques/volume/ShadowVolumeMesh (GPU Gems ch. 9, sections 9.2.2-9.3.6 and 9.5.1): welding
// and adjacency against the counts of the generators' closed forms (Euler characteristic), the volumes
// against the topological rule that makes stencil counting work (a closed, consistently oriented
// surface: every directed edge matched by its reverse) and against closed-form volumes, and the
// vertex-shader extrusion mesh against the CPU volume.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "core/Paths.h"
#include "scenes/MeshGenerators.h"
#include "techniques/volume/ShadowVolumeMesh.h"
#include "techniques/volume/SilhouetteInputs.h"

using namespace sb;

namespace {

Mesh teapot() {
    const std::string path = Paths::findResource("scenes/data/teapot.bpt");
    EXPECT_FALSE(path.empty()) << "scenes/data/teapot.bpt not found";
    return MeshGenerators::teapot(path, 8);
}

Mesh triangleMesh(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices) {
    Mesh m;
    m.name = "hand-made";
    m.positions = positions;
    m.normals.assign(positions.size(), glm::vec3(0.0f, 0.0f, 1.0f));
    m.indices = indices;
    return m;
}

long eulerCharacteristic(const ShadowVolumeMesh& m) {
    return long(m.vertexCount()) - long(m.edgeCount()) + long(m.faceCount());
}

VolumeIndices build(const ShadowVolumeMesh& m, const glm::vec4& light, OpenEdgePolicy policy,
                    bool directionalForm = false) {
    VolumeRequest r;
    r.light = light;
    r.policy = policy;
    r.directionalForm = directionalForm;
    VolumeIndices out;
    m.buildVolume(r, out);
    return out;
}

/// Undirected vertex pairs whose directed edges a -> b and b -> a occur a different number of times
/// over all triangles of `v`. Zero means a closed, consistently oriented surface (as a chain: a side
/// drawn twice counts twice each way), which is what makes the stencil count of every ray from
/// outside return to zero.
size_t unbalancedEdges(const VolumeIndices& v) {
    std::map<std::pair<uint32_t, uint32_t>, int> balance;
    for (const auto* list : {&v.lightCap, &v.darkCap, &v.sides}) {
        EXPECT_EQ(list->size() % 3, 0u);
        for (size_t t = 0; t + 2 < list->size(); t += 3)
            for (size_t k = 0; k < 3; ++k) {
                const uint32_t a = (*list)[t + k], b = (*list)[t + (k + 1) % 3];
                if (a < b)
                    ++balance[{a, b}];
                else
                    --balance[{b, a}];
            }
    }
    return size_t(std::count_if(balance.begin(), balance.end(), [](const auto& e) { return e.second != 0; }));
}

/// Signed volume (divergence theorem, positive for outward winding) of the volume made finite: a
/// w = 0 vertex p becomes p + 100 (p - light) for a point light, p - 100 L for a directional one.
double finiteVolume(const ShadowVolumeMesh& m, const VolumeIndices& v, const glm::vec4& light) {
    const uint32_t n = m.vertexCount();
    auto at = [&](uint32_t i) {
        const glm::dvec3 p(m.positions()[i % n]);
        if (i < n) return p;
        return light.w != 0.0f ? p + 100.0 * (p - glm::dvec3(light) / double(light.w))
                               : p - 100.0 * glm::dvec3(light);
    };
    double volume = 0.0;
    for (const auto* list : {&v.lightCap, &v.darkCap, &v.sides})
        for (size_t t = 0; t + 2 < list->size(); t += 3)
            volume += glm::dot(at((*list)[t]), glm::cross(at((*list)[t + 1]), at((*list)[t + 2]))) / 6.0;
    return volume;
}

/// Signed volume of the welded mesh itself, each vertex mapped by `map`.
template <typename Map>
double meshVolume(const ShadowVolumeMesh& m, Map map) {
    double volume = 0.0;
    for (size_t f = 0; f < m.faceCount(); ++f) {
        const glm::dvec3 a = map(glm::dvec3(m.positions()[m.faces()[3 * f]]));
        const glm::dvec3 b = map(glm::dvec3(m.positions()[m.faces()[3 * f + 1]]));
        const glm::dvec3 c = map(glm::dvec3(m.positions()[m.faces()[3 * f + 2]]));
        volume += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return volume;
}

/// A triangle as a tuple rotated to start at its smallest element: equal for the same triangle with
/// the same winding, whatever vertex it was written from.
template <typename T>
std::array<T, 3> canonical(T a, T b, T c) {
    std::array<T, 3> t{a, b, c};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    return t;
}
using Triangles = std::vector<std::array<uint32_t, 3>>;
Triangles sortedTriangles(const std::vector<uint32_t>& list) {
    Triangles out;
    for (size_t t = 0; t + 2 < list.size(); t += 3)
        out.push_back(canonical(list[t], list[t + 1], list[t + 2]));
    std::sort(out.begin(), out.end());
    return out;
}

struct Named {
    std::string name;
    Mesh mesh;
};
std::vector<Named> closedMeshes() {
    return {{"sphere", MeshGenerators::sphere(12)},
            {"box", MeshGenerators::box(glm::vec3(1.0f, 0.5f, 2.0f), 3)},
            {"cylinder", MeshGenerators::cylinder(6)},
            {"aircraft", MeshGenerators::aircraft(8)}};
}

// Lights in general position (no face plane through them, nothing exactly grazing): a point light
// outside every test mesh, one nearer and off to the side, and two oblique directional lights.
const glm::vec4 kLights[] = {{3.0f, 4.0f, 2.5f, 1.0f},
                             {-2.2f, 0.7f, -3.1f, 1.0f},
                             {0.3f, 1.0f, 0.2f, 0.0f},
                             {-0.6f, -0.45f, 0.7f, 0.0f}};

} // namespace

TEST(ShadowVolumeMeshTest, WeldedBoxIsClosedWithEulerCharacteristicTwo) {
    const glm::vec3 half(1.0f, 0.5f, 2.0f);
    for (int tess : {1, 2, 5}) {
        const Mesh mesh = MeshGenerators::box(half, tess);
        const ShadowVolumeMesh m(mesh);
        // A tess x tess grid on each of 6 faces: the welded surface has 6 tess^2 + 2 vertices (Euler),
        // 12 tess^2 triangles and 3/2 as many edges; each face grid has (tess + 1)^2 own vertices.
        EXPECT_EQ(m.vertexCount(), uint32_t(6 * tess * tess + 2)) << tess;
        EXPECT_EQ(m.faceCount(), size_t(12 * tess * tess));
        EXPECT_EQ(m.edgeCount(), size_t(18 * tess * tess));
        EXPECT_EQ(m.openEdgeCount(), 0u);
        EXPECT_TRUE(m.closed());
        EXPECT_EQ(m.collapsedFaceCount(), 0u);
        EXPECT_EQ(m.weldedAway(), mesh.vertexCount() - m.vertexCount());
        EXPECT_EQ(eulerCharacteristic(m), 2);
    }
}

TEST(ShadowVolumeMeshTest, WeldedSphereIsClosedWithEulerCharacteristicTwo) {
    for (int tess : {3, 8, 16}) {
        const ShadowVolumeMesh m(MeshGenerators::sphere(tess));
        // tess - 1 inner rings of 2 tess vertices plus the two poles; 4 tess (tess - 1) triangles
        // (the generator leaves out the degenerate halves of the pole quads: nothing collapses).
        EXPECT_EQ(m.vertexCount(), uint32_t(2 * tess * (tess - 1) + 2)) << tess;
        EXPECT_EQ(m.faceCount(), size_t(4 * tess * (tess - 1)));
        EXPECT_EQ(m.collapsedFaceCount(), 0u);
        EXPECT_EQ(m.openEdgeCount(), 0u);
        EXPECT_EQ(eulerCharacteristic(m), 2);
    }
}

TEST(ShadowVolumeMeshTest, CylinderAircraftAndLanternWeldClosed) {
    for (int tess : {2, 6}) {
        const ShadowVolumeMesh m(MeshGenerators::cylinder(tess));
        // tess + 1 rings of 2 tess around the side (the caps' rings weld onto the end rings) plus
        // the two cap centres; a sphere topologically.
        EXPECT_EQ(m.vertexCount(), uint32_t(2 * tess * (tess + 1) + 2));
        EXPECT_EQ(m.openEdgeCount(), 0u);
        EXPECT_EQ(eulerCharacteristic(m), 2);
    }
    for (int tess : {2, 8, 16}) {
        const ShadowVolumeMesh m(MeshGenerators::aircraft(tess));
        EXPECT_EQ(m.openEdgeCount(), 0u) << "aircraft " << tess;
        EXPECT_GT(m.weldedAway(), 0u);
    }
    // Genus 3 (four tunnels through a shell, documented in MeshGenerators.h): V - E + F = -4.
    const ShadowVolumeMesh lantern(MeshGenerators::lantern(0.08f, 16));
    EXPECT_EQ(lantern.openEdgeCount(), 0u);
    EXPECT_EQ(eulerCharacteristic(lantern), -4);
}

TEST(ShadowVolumeMeshTest, TeapotIsOpen) {
    const Mesh mesh = teapot();
    const ShadowVolumeMesh m(mesh);
    std::printf("teapot(8): %u welded vertices of %zu, %zu faces, %zu collapsed, %zu edges, %zu open\n",
                m.vertexCount(), mesh.vertexCount(), m.faceCount(), m.collapsedFaceCount(), m.edgeCount(),
                m.openEdgeCount());
    // The lid/body seam and the handle and spout joints are left open by the patch data.
    EXPECT_GT(m.openEdgeCount(), 0u);
    EXPECT_FALSE(m.closed());
    // The lid knob and bottom patches have a row of coincident control points: their pole triangles
    // collapse once welded.
    EXPECT_GT(m.collapsedFaceCount(), 0u);
    EXPECT_EQ(m.faceCount() + m.collapsedFaceCount(), mesh.triangleCount());
}

TEST(ShadowVolumeMeshTest, SingleTriangleHasThreeOpenEdgesInTheChaptersConvention) {
    const ShadowVolumeMesh m(triangleMesh({{0, 0, 0}, {2, 0, 0}, {0, 3, 0}}, {0, 1, 2}));
    ASSERT_EQ(m.edgeCount(), 3u);
    EXPECT_EQ(m.openEdgeCount(), 3u);
    // Unnormalised normal: cross((2,0,0), (0,3,0)) = (0, 0, 6), twice the area along +z.
    EXPECT_EQ(m.faceNormals()[0], glm::vec3(0.0f, 0.0f, 6.0f));
    EXPECT_EQ(m.facePlane(0), glm::vec4(0.0f, 0.0f, 6.0f, 0.0f));
    const auto& e = m.edges();
    const auto& fe = m.faceEdges();
    ASSERT_EQ(fe.size(), 3u);
    // Directed edges 0->1, 1->2 run low -> high: face0; 2->0 runs high -> low: face1, reversed.
    const ShadowVolumeMesh::Edge& e01 = e[fe[0] & ~ShadowVolumeMesh::kReversed];
    const ShadowVolumeMesh::Edge& e12 = e[fe[1] & ~ShadowVolumeMesh::kReversed];
    const ShadowVolumeMesh::Edge& e20 = e[fe[2] & ~ShadowVolumeMesh::kReversed];
    EXPECT_EQ(fe[0] & ShadowVolumeMesh::kReversed, 0u);
    EXPECT_EQ(fe[1] & ShadowVolumeMesh::kReversed, 0u);
    EXPECT_EQ(fe[2] & ShadowVolumeMesh::kReversed, ShadowVolumeMesh::kReversed);
    EXPECT_EQ(std::tie(e01.v0, e01.v1, e01.face0, e01.face1),
              std::make_tuple(0u, 1u, 0u, ShadowVolumeMesh::kNoFace));
    EXPECT_EQ(std::tie(e12.v0, e12.v1, e12.face0, e12.face1),
              std::make_tuple(1u, 2u, 0u, ShadowVolumeMesh::kNoFace));
    EXPECT_EQ(std::tie(e20.v0, e20.v1, e20.face0, e20.face1),
              std::make_tuple(0u, 2u, ShadowVolumeMesh::kNoFace, 0u));
}

TEST(ShadowVolumeMeshTest, EdgesFollowTheChaptersOrientationConvention) {
    // Section 9.2.2: v0 -> v1 counter-clockwise (in order) in face0, clockwise in face1; and each
    // face's three directed edges point at edges with the matching direction flag.
    for (const auto& [name, mesh] : closedMeshes()) {
        const ShadowVolumeMesh m(mesh);
        auto traverses = [&](uint32_t f, uint32_t a, uint32_t b) {
            const uint32_t* v = &m.faces()[3 * f];
            return (v[0] == a && v[1] == b) || (v[1] == a && v[2] == b) || (v[2] == a && v[0] == b);
        };
        for (const auto& e : m.edges()) {
            ASSERT_NE(e.face0, ShadowVolumeMesh::kNoFace) << name;
            ASSERT_NE(e.face1, ShadowVolumeMesh::kNoFace) << name;
            EXPECT_TRUE(traverses(e.face0, e.v0, e.v1)) << name;
            EXPECT_TRUE(traverses(e.face1, e.v1, e.v0)) << name;
        }
        for (size_t f = 0; f < m.faceCount(); ++f)
            for (size_t k = 0; k < 3; ++k) {
                const uint32_t fe = m.faceEdges()[3 * f + k];
                const auto& e = m.edges()[fe & ~ShadowVolumeMesh::kReversed];
                const uint32_t a = m.faces()[3 * f + k], b = m.faces()[3 * f + (k + 1) % 3];
                if (fe & ShadowVolumeMesh::kReversed)
                    EXPECT_TRUE(e.v1 == a && e.v0 == b) << name;
                else
                    EXPECT_TRUE(e.v0 == a && e.v1 == b) << name;
            }
    }
}

TEST(ShadowVolumeMeshTest, WeldMergesPointsWithinToleranceAcrossCellBorders) {
    // Tolerance 1e-3 of the extent ~1: weld distance ~1e-3, which is also the grid's cell size. The
    // second copies of the quad's diagonal ends straddle cell borders (x = 3e-3 and z = 0, y = 1)
    // while lying ~1e-6 << 1e-3 from the first: a grid that only compared equal cells would keep them apart.
    const glm::vec3 a(0.0029995f, 0.0f, -5e-7f), aCopy(0.0030005f, 0.0f, 5e-7f);
    const glm::vec3 c(1.0f, 0.9999995f, 0.0f), cCopy(1.0f, 1.0000005f, 0.0f);
    // An unused vertex 2e-3 from b (twice the distance) must stay apart.
    const glm::vec3 b(1.0f, 0.0f, 0.0f), d(0.0f, 1.0f, 0.0f), nearB(1.0f, 0.002f, 0.0f);
    const ShadowVolumeMesh m(triangleMesh({a, b, c, aCopy, cCopy, d, nearB}, {0, 1, 2, 3, 4, 5}), 1e-3f);
    EXPECT_EQ(m.weldedAway(), 2u);
    ASSERT_EQ(m.vertexCount(), 5u);
    EXPECT_EQ(m.positions()[4], nearB);
    EXPECT_EQ(m.faces(), (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
    // The quad's 4 border edges are cracks; its diagonal a-c has one face each way.
    EXPECT_EQ(m.edgeCount(), 5u);
    EXPECT_EQ(m.openEdgeCount(), 4u);
}

TEST(ShadowVolumeMeshTest, CollapsedFacesAreDroppedAndSliversKept) {
    // Face 1 has two vertices 1e-8 apart (welded: collapsed); face 2 has three distinct collinear
    // vertices: zero area, kept, with a zero normal that classifies as light-facing.
    const Mesh mesh = triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1e-8f, 0}, {2, 0, 0}},
                                   {0, 1, 2, 1, 3, 2, 0, 1, 4});
    const ShadowVolumeMesh m(mesh);
    EXPECT_EQ(m.collapsedFaceCount(), 1u);
    EXPECT_EQ(m.weldedAway(), 1u);
    ASSERT_EQ(m.faceCount(), 2u);
    EXPECT_EQ(m.faceNormals()[1], glm::vec3(0.0f));
    std::vector<uint8_t> back;
    m.classifyFaces({0.0f, 0.0f, -1.0f, 0.0f}, back); // from below: face 0 is a back face
    EXPECT_EQ(back, (std::vector<uint8_t>{1, 0}));
}

TEST(ShadowVolumeMeshTest, ClassifyFacesFollowsListing95) {
    // One triangle in z = 0 with normal +z: lights on the +z side see its front.
    const ShadowVolumeMesh m(triangleMesh({{0, 0, 0}, {2, 0, 0}, {0, 3, 0}}, {0, 1, 2}));
    std::vector<uint8_t> back;
    const std::pair<glm::vec4, uint8_t> cases[] = {
        {{5.0f, -7.0f, 1.0f, 1.0f}, 0},  // point above the plane (far off to the side)
        {{0.5f, 0.5f, -0.1f, 1.0f}, 1},  // point just below
        {{0.0f, 0.0f, 1.0f, 0.0f}, 0},   // directional, vector towards the light +z
        {{1.0f, 1.0f, -0.2f, 0.0f}, 1},  // directional from below
        {{10.0f, 10.0f, 0.0f, 1.0f}, 0}, // in the plane: N.L = 0 is not < 0, light-facing
    };
    for (const auto& [light, expected] : cases) {
        m.classifyFaces(light, back);
        ASSERT_EQ(back.size(), 1u);
        EXPECT_EQ(back[0], expected) << light.x << " " << light.y << " " << light.z << " " << light.w;
    }
}

TEST(ShadowVolumeMeshTest, DoubledVerticesAreFiniteThenAtInfinity) {
    const ShadowVolumeMesh m(MeshGenerators::box(glm::vec3(1.0f), 1));
    const std::vector<glm::vec4> v = m.doubledVertices();
    const uint32_t n = m.vertexCount();
    ASSERT_EQ(v.size(), 2u * n);
    for (uint32_t i = 0; i < n; ++i) {
        EXPECT_EQ(v[i], glm::vec4(m.positions()[i], 1.0f));
        EXPECT_EQ(v[n + i], glm::vec4(m.positions()[i], 0.0f));
    }
}

TEST(ShadowVolumeMeshTest, BoxUnderOverheadDirectionalLightHasTheBottomRimAsSilhouette) {
    // Light straight above (L = +y, w = 0). The top faces have N.L > 0; the side faces' normals are
    // exactly horizontal (their vertices share x or z bit for bit, so the cross product's y is an
    // exact 0): N.L = 0, not < 0, so they are light-facing too. Only the bottom is light-back, and the
    // silhouette is the bottom rim: 4 tess edges, all at y = -half.y.
    const glm::vec3 half(1.0f, 0.5f, 2.0f);
    const glm::vec4 light(0.0f, 1.0f, 0.0f, 0.0f);
    for (int tess : {1, 3}) {
        const ShadowVolumeMesh m(MeshGenerators::box(half, tess));
        const uint32_t n = m.vertexCount();
        const VolumeIndices v = build(m, light, OpenEdgePolicy::Closed);
        EXPECT_EQ(v.silhouetteEdges, uint32_t(4 * tess));
        EXPECT_EQ(v.lightCap.size(), size_t(3 * 5 * 2 * tess * tess)); // top and 4 sides
        EXPECT_EQ(v.darkCap.size(), size_t(3 * 2 * tess * tess));      // bottom at infinity
        EXPECT_EQ(v.sides.size(), size_t(6 * 4 * tess));               // one quad per rim edge
        for (uint32_t i : v.sides) EXPECT_EQ(m.positions()[i % n].y, -half.y);
        for (uint32_t i : v.darkCap) {
            EXPECT_GE(i, n);
            EXPECT_EQ(m.positions()[i - n].y, -half.y);
        }
        // Directional form: one triangle per silhouette edge, converging on vertex n; no dark cap.
        const VolumeIndices d = build(m, light, OpenEdgePolicy::Closed, true);
        EXPECT_EQ(d.silhouetteEdges, uint32_t(4 * tess));
        EXPECT_EQ(d.sides.size(), size_t(3 * 4 * tess));
        EXPECT_TRUE(d.darkCap.empty());
        for (size_t t = 0; t < d.sides.size(); t += 3) EXPECT_EQ(d.sides[t + 2], n);
        EXPECT_EQ(unbalancedEdges(v), 0u);
        EXPECT_EQ(unbalancedEdges(d), 0u);
    }
}

TEST(ShadowVolumeMeshTest, VolumesAreClosedOrientedSurfacesForClosedMeshes) {
    for (const auto& [name, mesh] : closedMeshes()) {
        const ShadowVolumeMesh m(mesh);
        for (const glm::vec4& light : kLights)
            for (OpenEdgePolicy policy : {OpenEdgePolicy::Closed, OpenEdgePolicy::Multiplicity})
                for (bool form : {false, true}) {
                    if (form && light.w != 0.0f) continue;
                    const VolumeIndices v = build(m, light, policy, form);
                    const std::string what =
                        name + (policy == OpenEdgePolicy::Closed ? " closed" : " multiplicity") +
                        (form ? " directional form" : "") + " light " + std::to_string(&light - kLights);
                    EXPECT_GT(v.silhouetteEdges, 0u) << what;
                    EXPECT_EQ(unbalancedEdges(v), 0u) << what;
                    if (form) {
                        // Section 9.5.1: one triangle per silhouette edge (twice under multiplicity,
                        // where a closed mesh's silhouette edges have |m| = 2).
                        const uint32_t copies = policy == OpenEdgePolicy::Closed ? 1 : 2;
                        EXPECT_EQ(v.sides.size(), size_t(3 * copies * v.silhouetteEdges)) << what;
                        EXPECT_TRUE(v.darkCap.empty()) << what;
                    }
                }
    }
}

TEST(ShadowVolumeMeshTest, MultiplicityVolumesAreClosedForOpenMeshes) {
    // The robust policy must close the volume whatever the mesh: the teapot (cracks, collapsed pole
    // faces) and a lone triangle.
    const ShadowVolumeMesh pot(teapot());
    const ShadowVolumeMesh tri(triangleMesh({{0, 0, 0}, {2, 0, 0}, {0, 3, 0}}, {0, 1, 2}));
    for (const ShadowVolumeMesh* m : {&pot, &tri})
        for (const glm::vec4& light : kLights)
            for (bool form : {false, true}) {
                if (form && light.w != 0.0f) continue;
                const VolumeIndices v = build(*m, light, OpenEdgePolicy::Multiplicity, form);
                EXPECT_GT(v.silhouetteEdges, 0u);
                EXPECT_EQ(unbalancedEdges(v), 0u)
                    << m->name() << " light " << (&light - kLights) << " form " << form;
            }
}

TEST(ShadowVolumeMeshTest, MultiplicityOnOneTriangleMatchesTheHandBuiltVolume) {
    const ShadowVolumeMesh m(triangleMesh({{0, 0, 0}, {2, 0, 0}, {0, 3, 0}}, {0, 1, 2}));
    // n = 3. Lit from above (+z): the face keeps its winding 0 1 2; the dark cap is it reversed at
    // infinity; each edge has m = +1 (0->1, 1->2 run low -> high) or -1 (2->0), and the side contains
    // the edge against the light cap's direction: 1->0, 2->1, 0->2.
    VolumeIndices v = build(m, {0.5f, 0.5f, 4.0f, 1.0f}, OpenEdgePolicy::Multiplicity);
    EXPECT_EQ(v.lightCap, (std::vector<uint32_t>{0, 1, 2}));
    EXPECT_EQ(v.darkCap, (std::vector<uint32_t>{3, 5, 4}));
    EXPECT_EQ(v.silhouetteEdges, 3u);
    EXPECT_EQ(sortedTriangles(v.sides), sortedTriangles({1, 0, 3, 1, 3, 4,    // edge 0-1: quad 1 0 0' 1'
                                                         2, 1, 4, 2, 4, 5,    // edge 1-2: quad 2 1 1' 2'
                                                         0, 2, 5, 0, 5, 3})); // edge 0-2: quad 0 2 2' 0'
    // Lit from below: flipped to 0 2 1, the dark cap is the original winding at infinity, the sides
    // run the other way.
    v = build(m, {0.5f, 0.5f, -4.0f, 1.0f}, OpenEdgePolicy::Multiplicity);
    EXPECT_EQ(v.lightCap, (std::vector<uint32_t>{0, 2, 1}));
    EXPECT_EQ(v.darkCap, (std::vector<uint32_t>{3, 4, 5}));
    EXPECT_EQ(sortedTriangles(v.sides), sortedTriangles({0, 1, 4, 0, 4, 3,    // quad 0 1 1' 0'
                                                         1, 2, 5, 1, 5, 4,    // quad 1 2 2' 1'
                                                         2, 0, 3, 2, 3, 5})); // quad 2 0 0' 2'
    // The Closed policy skips open edges: caps only.
    v = build(m, {0.5f, 0.5f, 4.0f, 1.0f}, OpenEdgePolicy::Closed);
    EXPECT_TRUE(v.sides.empty());
    EXPECT_EQ(v.silhouetteEdges, 0u);
}

TEST(ShadowVolumeMeshTest, MultiplicityOfAClosedMeshIsClosedsSidesTwice) {
    // For a closed mesh every silhouette edge has |m| = 2 and the side must be wound as Listing 9-7's
    // (the chapter's rule fixes it): the sides are Closed's sides, each twice, same winding. The light
    // cap adds the flipped back faces, the dark cap the reversed front faces at infinity.
    for (const auto& [name, mesh] : closedMeshes()) {
        const ShadowVolumeMesh m(mesh);
        for (const glm::vec4& light : kLights)
            for (bool form : {false, true}) {
                if (form && light.w != 0.0f) continue;
                const VolumeIndices closed = build(m, light, OpenEdgePolicy::Closed, form);
                const VolumeIndices multi = build(m, light, OpenEdgePolicy::Multiplicity, form);
                std::vector<uint32_t> twice = closed.sides;
                twice.insert(twice.end(), closed.sides.begin(), closed.sides.end());
                EXPECT_EQ(sortedTriangles(multi.sides), sortedTriangles(twice)) << name;
                EXPECT_EQ(multi.silhouetteEdges, closed.silhouetteEdges) << name;
                EXPECT_EQ(multi.lightCap.size(), 3 * m.faceCount()) << name;
                EXPECT_EQ(multi.darkCap.size(), form ? 0 : 3 * m.faceCount()) << name;
            }
    }
}

TEST(ShadowVolumeMeshTest, FiniteVolumeOfABoxMatchesClosedForms) {
    const glm::vec3 h(0.5f, 0.75f, 1.0f);
    const ShadowVolumeMesh m(MeshGenerators::box(h, 2));
    // Volumes in double from float corners that are exact binary fractions: only double rounding of
    // sums of ~1e8, relative 1e-12; 1e-9 relative leaves room.
    auto near = [](double a, double b) { return std::abs(a - b) <= 1e-9 * std::abs(b); };
    // Directional from straight above, w = 0 vertices moved 100 down: the box plus the prism swept by
    // its bottom (area 4 h.x h.z) over 100.
    {
        const glm::vec4 light(0.0f, 1.0f, 0.0f, 0.0f);
        const double expected = 8.0 * h.x * h.y * h.z + 100.0 * 4.0 * h.x * h.z;
        const double got = finiteVolume(m, build(m, light, OpenEdgePolicy::Closed), light);
        EXPECT_TRUE(near(got, expected)) << got << " vs " << expected;
    }
    // Point light 5 above the centre: the top is lit, sides and bottom are back faces, the silhouette
    // is the top rim. w = 0 vertices p -> L + 101 (p - L): the pyramid frustum from the top face (area
    // A0 at distance d0 from the light) to its 101x image, plus the 101x image of the box.
    {
        const glm::vec4 light(0.0f, 5.0f, 0.0f, 1.0f);
        const double a0 = 4.0 * h.x * h.z, d0 = 5.0 - h.y, k = 101.0 * 101.0 * 101.0;
        const double expected = a0 * d0 * (k - 1.0) / 3.0 + k * 8.0 * h.x * h.y * h.z;
        const VolumeIndices v = build(m, light, OpenEdgePolicy::Closed);
        EXPECT_EQ(v.silhouetteEdges, 4u * 2u);
        const double got = finiteVolume(m, v, light);
        EXPECT_TRUE(near(got, expected)) << got << " vs " << expected;
    }
}

TEST(ShadowVolumeMeshTest, FiniteVolumesAreOutwardAndMultiplicityCountsTwice) {
    // Outward orientation: positive signed volume (the stencil count is >= 0 everywhere). Multiplicity
    // against Closed, as chains: Multi = 2 Closed - (mesh) - (mesh's image), because the flipped back
    // faces and reversed front faces at infinity add exactly the caster and its image with a minus.
    // With the point-light map the image is the mesh scaled 101x about the light.
    for (const auto& [name, mesh] : closedMeshes()) {
        const ShadowVolumeMesh m(mesh);
        for (const glm::vec4& light : kLights) {
            if (light.w == 0.0f) continue;
            const glm::dvec3 l(light);
            const double closed = finiteVolume(m, build(m, light, OpenEdgePolicy::Closed), light);
            const double multi = finiteVolume(m, build(m, light, OpenEdgePolicy::Multiplicity), light);
            const double caster = meshVolume(m, [](const glm::dvec3& p) { return p; });
            const double image = meshVolume(m, [&](const glm::dvec3& p) { return p + 100.0 * (p - l); });
            EXPECT_GT(caster, 0.0) << name;
            EXPECT_GT(closed, 0.0) << name;
            EXPECT_GT(multi, 0.0) << name;
            // Same float inputs on both sides, sums in double: 1e-9 relative of the largest term.
            EXPECT_NEAR(multi, 2.0 * closed - caster - image, 1e-9 * std::abs(image)) << name;
        }
    }
}

TEST(ShadowVolumeMeshTest, BuildVolumeHonoursTheRequestAndReusesStorage) {
    const ShadowVolumeMesh m(MeshGenerators::sphere(8));
    VolumeRequest r;
    r.light = {2.0f, 3.0f, 1.0f, 1.0f};
    VolumeIndices v;
    m.buildVolume(r, v);
    const VolumeIndices full = v;
    ASSERT_FALSE(v.lightCap.empty());
    ASSERT_FALSE(v.darkCap.empty());
    ASSERT_FALSE(v.sides.empty());
    // A second build of the same request writes into the same storage (no reallocation).
    const uint32_t* pointers[3] = {v.lightCap.data(), v.darkCap.data(), v.sides.data()};
    m.buildVolume(r, v);
    EXPECT_EQ(v.lightCap.data(), pointers[0]);
    EXPECT_EQ(v.darkCap.data(), pointers[1]);
    EXPECT_EQ(v.sides.data(), pointers[2]);
    EXPECT_EQ(v.sides, full.sides);

    r.caps = false; // z-pass: sides only
    m.buildVolume(r, v);
    EXPECT_TRUE(v.lightCap.empty() && v.darkCap.empty());
    EXPECT_EQ(v.sides, full.sides);
    r.caps = true;
    r.lightCap = false;
    m.buildVolume(r, v);
    EXPECT_TRUE(v.lightCap.empty());
    EXPECT_EQ(v.darkCap, full.darkCap);
    r.lightCap = true;
    r.sides = false;
    m.buildVolume(r, v);
    EXPECT_TRUE(v.sides.empty());
    EXPECT_EQ(v.silhouetteEdges, 0u);
    EXPECT_EQ(v.lightCap, full.lightCap);
    // The directional form only applies to w = 0 lights.
    r.sides = true;
    r.directionalForm = true;
    m.buildVolume(r, v);
    EXPECT_EQ(v.sides, full.sides);
    EXPECT_EQ(v.darkCap, full.darkCap);
}

namespace {

using Hom = std::array<float, 4>;
Hom hom(const glm::vec4& p) {
    return {p.x, p.y, p.z, p.w};
}
/// Listing 9-3 and shaders/volume/extrude.vert: the image of p at infinity away from the light.
glm::vec4 extrude(const glm::vec3& p, const glm::vec4& light) {
    return glm::vec4(p * light.w - glm::vec3(light), 0.0f);
}

/// The VS_EXTRUSION vertex shader on the CPU: vertex i of `x` in homogeneous object space.
Hom shadeExtrusion(const ExtrusionMesh& x, uint32_t i, const glm::vec4& light) {
    const glm::vec4& plane = x.facePlanes[i];
    const bool back = glm::dot(glm::vec3(plane), glm::vec3(light)) - light.w * plane.w < 0.0f;
    return hom(back ? extrude(x.positions[i], light) : glm::vec4(x.positions[i], 1.0f));
}

} // namespace

TEST(ShadowVolumeMeshTest, ExtrusionMeshInTheVertexShaderReproducesTheClosedVolume) {
    // The shader (VS_EXTRUSION) simulated on the CPU: a vertex goes to infinity iff its face's plane
    // (N, d) has dot(N, L.xyz) - L.w d < 0. Side triangles that open must be exactly buildVolume's
    // Closed sides (same homogeneous vertices, same winding; the lights are in general position, so
    // the plane form and Listing 9-5's dot(N, L - P0 L.w) classify alike despite rounding), the
    // others must collapse (two identical vertices: zero area); caps must be Closed's light cap plus
    // dark cap.
    for (const auto& [name, mesh] : closedMeshes()) {
        const ShadowVolumeMesh m(mesh);
        const ExtrusionMesh x = m.buildExtrusionMesh();
        ASSERT_EQ(x.positions.size(), x.facePlanes.size());
        EXPECT_FALSE(x.twoSheets);
        EXPECT_EQ(x.capIndices.size(), 3 * m.faceCount());
        EXPECT_EQ(x.sideIndices.size(), 6 * m.edgeCount()); // closed: every edge has both faces
        EXPECT_EQ(x.positions.size(), 3 * m.faceCount() + 4 * m.edgeCount());
        const uint32_t n = m.vertexCount();
        for (const glm::vec4& light : kLights) {
            auto shade = [&](uint32_t i) { return shadeExtrusion(x, i, light); };
            auto doubled = [&](uint32_t i) {
                return hom(i < n ? glm::vec4(m.positions()[i], 1.0f) : extrude(m.positions()[i - n], light));
            };
            std::vector<std::array<Hom, 3>> open, expected;
            size_t degenerate = 0;
            for (size_t t = 0; t < x.sideIndices.size(); t += 3) {
                const Hom a = shade(x.sideIndices[t]), b = shade(x.sideIndices[t + 1]),
                          c = shade(x.sideIndices[t + 2]);
                if (a == b || b == c || c == a)
                    ++degenerate;
                else
                    open.push_back(canonical(a, b, c));
            }
            VolumeRequest r;
            r.light = light;
            VolumeIndices v;
            m.buildVolume(r, v);
            // For a directional light both w = 0 ends of a side are the one point -L: one triangle of
            // each quad is degenerate in buildVolume's output too, and left out on both sides.
            for (size_t t = 0; t < v.sides.size(); t += 3) {
                const Hom a = doubled(v.sides[t]), b = doubled(v.sides[t + 1]), c = doubled(v.sides[t + 2]);
                if (!(a == b || b == c || c == a)) expected.push_back(canonical(a, b, c));
            }
            std::sort(open.begin(), open.end());
            std::sort(expected.begin(), expected.end());
            EXPECT_EQ(open, expected) << name << " light " << (&light - kLights);
            EXPECT_FALSE(open.empty()) << name;
            const size_t collapsedSides = light.w != 0.0f ? 0 : v.silhouetteEdges;
            EXPECT_EQ(degenerate, 2 * (m.edgeCount() - v.silhouetteEdges) + collapsedSides) << name;

            std::vector<std::array<Hom, 3>> caps, expectedCaps;
            for (size_t t = 0; t < x.capIndices.size(); t += 3)
                caps.push_back(canonical(shade(x.capIndices[t]), shade(x.capIndices[t + 1]),
                                         shade(x.capIndices[t + 2])));
            for (const auto* list : {&v.lightCap, &v.darkCap})
                for (size_t t = 0; t < list->size(); t += 3)
                    expectedCaps.push_back(
                        canonical(doubled((*list)[t]), doubled((*list)[t + 1]), doubled((*list)[t + 2])));
            std::sort(caps.begin(), caps.end());
            std::sort(expectedCaps.begin(), expectedCaps.end());
            EXPECT_EQ(caps, expectedCaps) << name << " light " << (&light - kLights);
        }
    }
}

TEST(ShadowVolumeMeshTest, ExtrusionMeshSkipsOpenEdgesUnderClosed) {
    const ShadowVolumeMesh m(triangleMesh({{0, 0, 0}, {2, 0, 0}, {0, 3, 0}}, {0, 1, 2}));
    const ExtrusionMesh x = m.buildExtrusionMesh(OpenEdgePolicy::Closed);
    EXPECT_EQ(x.positions.size(), 3u);
    EXPECT_EQ(x.capIndices, (std::vector<uint32_t>{0, 1, 2}));
    EXPECT_TRUE(x.sideIndices.empty());
    // N = (2,0,0) x (0,3,0) = (0,0,6); the plane passes through the origin.
    EXPECT_EQ(x.facePlanes[2], glm::vec4(0.0f, 0.0f, 6.0f, 0.0f));
}

TEST(ShadowVolumeMeshTest, ExtrusionMeshVerticesOfOneFaceCarryOnePlane) {
    // The shader's classification reads only the plane and the light: the vertices of a face (and of
    // each half of an edge quad) must carry the same plane, or a grazing light could split a face.
    const ShadowVolumeMesh m(MeshGenerators::aircraft(8));
    const ExtrusionMesh x = m.buildExtrusionMesh();
    for (size_t t = 0; t < x.capIndices.size(); t += 3) {
        ASSERT_EQ(x.facePlanes[x.capIndices[t]], x.facePlanes[x.capIndices[t + 1]]);
        ASSERT_EQ(x.facePlanes[x.capIndices[t]], x.facePlanes[x.capIndices[t + 2]]);
    }
    // The plane offset is dot(N, P) for every vertex of the face, up to float rounding relative to
    // |N| |P| (the mesh spans a few units).
    for (size_t i = 0; i < x.positions.size(); ++i) {
        const glm::vec3 n(x.facePlanes[i]);
        const float scale = glm::length(n) * std::max(1.0f, glm::length(x.positions[i]));
        EXPECT_NEAR(glm::dot(n, x.positions[i]), x.facePlanes[i].w, 1e-5f * scale) << i;
    }
}

TEST(ShadowVolumeMeshTest, TwoSheetExtrusionClosesOpenMeshesLikeMultiplicity) {
    // Multiplicity on an open mesh: the vertex-shader volume, as the shader would place its vertices,
    // must be a closed oriented surface (every directed edge between homogeneous points matched by its
    // reverse) for the teapot (cracks, pole fans) and a lone triangle, under every test light; the
    // lone triangle's must be exactly the CPU multiplicity volume (hand-checked in
    // MultiplicityOnOneTriangleMatchesTheHandBuiltVolume).
    const ShadowVolumeMesh pot(teapot());
    const ShadowVolumeMesh tri(triangleMesh({{0, 0, 0}, {2, 0, 0}, {0, 3, 0}}, {0, 1, 2}));
    for (const ShadowVolumeMesh* m : {&pot, &tri}) {
        const ExtrusionMesh x = m->buildExtrusionMesh(OpenEdgePolicy::Multiplicity);
        EXPECT_TRUE(x.twoSheets);
        EXPECT_EQ(x.capIndices.size(), 6 * m->faceCount());
        for (const glm::vec4& light : kLights) {
            std::map<std::pair<Hom, Hom>, int> balance;
            size_t openSides = 0;
            for (const auto* list : {&x.capIndices, &x.sideIndices})
                for (size_t t = 0; t < list->size(); t += 3) {
                    const Hom v[3] = {shadeExtrusion(x, (*list)[t], light),
                                      shadeExtrusion(x, (*list)[t + 1], light),
                                      shadeExtrusion(x, (*list)[t + 2], light)};
                    if (list == &x.sideIndices && v[0] != v[1] && v[1] != v[2] && v[2] != v[0]) ++openSides;
                    for (size_t k = 0; k < 3; ++k) {
                        const Hom &a = v[k], &b = v[(k + 1) % 3];
                        if (a < b)
                            ++balance[{a, b}];
                        else if (b < a)
                            --balance[{b, a}];
                    }
                }
            const size_t unbalanced = size_t(
                std::count_if(balance.begin(), balance.end(), [](const auto& e) { return e.second != 0; }));
            EXPECT_EQ(unbalanced, 0u) << m->name() << " light " << (&light - kLights);
            EXPECT_GT(openSides, 0u) << m->name();
        }
    }
    // The lone triangle lit from above by a point light: one light cap, one dark cap, and each of
    // the three edges opens into a quad (two triangles), as buildVolume's multiplicity sides.
    const ExtrusionMesh x = tri.buildExtrusionMesh(OpenEdgePolicy::Multiplicity);
    const glm::vec4 light(0.5f, 0.5f, 4.0f, 1.0f);
    VolumeRequest r;
    r.light = light;
    r.policy = OpenEdgePolicy::Multiplicity;
    VolumeIndices v;
    tri.buildVolume(r, v);
    auto doubled = [&](uint32_t i) {
        return hom(i < 3 ? glm::vec4(tri.positions()[i], 1.0f) : extrude(tri.positions()[i - 3], light));
    };
    std::vector<std::array<Hom, 3>> gpu, cpu;
    for (const auto* list : {&x.capIndices, &x.sideIndices})
        for (size_t t = 0; t < list->size(); t += 3) {
            const Hom a = shadeExtrusion(x, (*list)[t], light), b = shadeExtrusion(x, (*list)[t + 1], light),
                      c = shadeExtrusion(x, (*list)[t + 2], light);
            if (a != b && b != c && c != a) gpu.push_back(canonical(a, b, c));
        }
    for (const auto* list : {&v.lightCap, &v.darkCap, &v.sides})
        for (size_t t = 0; t < list->size(); t += 3)
            cpu.push_back(canonical(doubled((*list)[t]), doubled((*list)[t + 1]), doubled((*list)[t + 2])));
    std::sort(gpu.begin(), gpu.end());
    std::sort(cpu.begin(), cpu.end());
    EXPECT_EQ(gpu, cpu);
}

TEST(ShadowVolumeMeshTest, NonFinitePositionIsAnError) {
    const Mesh mesh = triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, std::nanf(""), 0}}, {0, 1, 2});
    EXPECT_THROW(ShadowVolumeMesh{mesh}, std::runtime_error);
    const Mesh bad = triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 3});
    EXPECT_THROW(ShadowVolumeMesh{bad}, std::runtime_error);
}

TEST(ShadowVolumeMeshTest, NeighboursTraverseEachEdgeTheOtherWay) {
    // The GPU silhouette paths' adjacency: on a closed mesh every directed edge a -> b of a face has a
    // neighbour traversing b -> a, whose neighbour across that edge is the face again.
    for (const auto& [name, mesh] : closedMeshes()) {
        const ShadowVolumeMesh m(mesh);
        const std::vector<uint32_t> nb = m.neighbours();
        const std::vector<uint32_t>& faces = m.faces();
        ASSERT_EQ(nb.size(), faces.size()) << name;
        for (size_t f = 0; f < m.faceCount(); ++f)
            for (size_t k = 0; k < 3; ++k) {
                const uint32_t g = nb[3 * f + k];
                ASSERT_NE(g, ShadowVolumeMesh::kNoFace) << name << " face " << f;
                const uint32_t a = faces[3 * f + k], b = faces[3 * f + (k + 1) % 3];
                int found = 0;
                for (size_t j = 0; j < 3; ++j)
                    if (faces[3 * g + j] == b && faces[3 * g + (j + 1) % 3] == a) {
                        ++found;
                        EXPECT_EQ(nb[3 * g + j], uint32_t(f)) << name << " face " << f;
                    }
                EXPECT_EQ(found, 1) << name << " face " << f << " edge " << k;
            }
    }
}

TEST(ShadowVolumeMeshTest, SilhouetteInputsCarryEachFacesOwnPlaneData) {
    // Triangles with adjacency: slot 2k + 1 is the vertex of the face across edge k that is not on the
    // edge, with that face's normal and first vertex, so the geometry shader classifies a neighbour from
    // the numbers it classifies that face itself by. The compute path's records agree with them.
    const ShadowVolumeMesh m(MeshGenerators::box(glm::vec3(1.0f, 0.5f, 2.0f), 2));
    const std::vector<glm::vec4> adj = SilhouetteInputs::adjacencyVertices(m);
    const std::vector<SilhouetteFace> faces = SilhouetteInputs::faces(m);
    ASSERT_EQ(adj.size(), m.faceCount() * 18);
    ASSERT_EQ(faces.size(), m.faceCount());
    const auto& p = m.positions();
    for (size_t f = 0; f < m.faceCount(); ++f) {
        const glm::vec4* v = &adj[18 * f];
        for (size_t k = 0; k < 3; ++k) {
            const uint32_t a = m.faces()[3 * f + k], b = m.faces()[3 * f + (k + 1) % 3];
            EXPECT_EQ(glm::vec3(v[6 * k]), p[a]);
            EXPECT_EQ(glm::vec3(v[6 * k + 1]), m.faceNormals()[f]);
            const uint32_t g = faces[f].neighbours[int(k)];
            EXPECT_NE(g, uint32_t(f));
            EXPECT_EQ(glm::vec3(v[6 * k + 4]), m.faceNormals()[g]) << f << " " << k;
            EXPECT_EQ(glm::vec3(v[6 * k + 5]), glm::vec3(faces[g].first));
            const glm::vec3 opposite(v[6 * k + 3]);
            EXPECT_TRUE(opposite != p[a] && opposite != p[b]) << f << " " << k;
        }
    }
}
