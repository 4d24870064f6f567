// Unit tests of scenes/MeshGenerators: counts from the documented tessellation rules, closedness and
// winding from the welded edge structure, volumes against the analytic shapes.
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include "core/Paths.h"
#include "scenes/MeshGenerators.h"

using namespace sb;

namespace {

/// Welds positions closer than `eps` (the generators duplicate seam and face-border vertices on
/// purpose, for normals): returns a representative index per vertex.
std::vector<uint32_t> weld(const std::vector<glm::vec3>& positions, float eps = 1e-5f) {
    std::vector<uint32_t> order(positions.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(),
              [&](uint32_t a, uint32_t b) { return positions[a].x < positions[b].x; });
    std::vector<uint32_t> rep(positions.size());
    std::iota(rep.begin(), rep.end(), 0u);
    for (size_t i = 0; i < order.size(); ++i) {
        for (size_t j = i; j-- > 0;) {
            if (positions[order[i]].x - positions[order[j]].x > eps) break;
            if (glm::length(positions[order[i]] - positions[order[j]]) <= eps) {
                rep[order[i]] = rep[order[j]];
                break;
            }
        }
    }
    return rep;
}

/// Triangles [first, first + count) of `mesh` as index triples.
struct Range {
    size_t firstTriangle = 0, triangleCount = 0;
};
Range wholeMesh(const Mesh& m) {
    return {0, m.triangleCount()};
}
Range partRange(const Mesh& m, const std::string& name) {
    for (const auto& p : m.parts)
        if (p.name == name) return {p.firstIndex / 3, p.indexCount / 3};
    ADD_FAILURE() << "no part " << name;
    return {};
}

/// Closed and consistently wound: after welding, every directed edge occurs exactly once and its
/// reverse exactly once (so every undirected edge has exactly two faces, wound oppositely).
void expectClosed(const Mesh& m, Range r, const std::string& what) {
    const auto rep = weld(m.positions);
    std::map<std::pair<uint32_t, uint32_t>, int> directed;
    for (size_t t = r.firstTriangle; t < r.firstTriangle + r.triangleCount; ++t) {
        const uint32_t v[3] = {rep[m.indices[3 * t]], rep[m.indices[3 * t + 1]], rep[m.indices[3 * t + 2]]};
        ASSERT_TRUE(v[0] != v[1] && v[1] != v[2] && v[0] != v[2]) << what << ": degenerate triangle " << t;
        for (int k = 0; k < 3; ++k) ++directed[{v[k], v[(k + 1) % 3]}];
    }
    int bad = 0;
    for (const auto& [edge, count] : directed) {
        const auto reverse = directed.find({edge.second, edge.first});
        if (count != 1 || reverse == directed.end() || reverse->second != 1) ++bad;
    }
    EXPECT_EQ(bad, 0) << what << ": edges not shared by exactly two oppositely wound faces";
}

/// Signed volume by the divergence theorem: positive for outward (counter-clockwise) winding.
double signedVolume(const Mesh& m, Range r) {
    double v = 0.0;
    for (size_t t = r.firstTriangle; t < r.firstTriangle + r.triangleCount; ++t) {
        const glm::dvec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                         c = m.positions[m.indices[3 * t + 2]];
        v += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return v;
}

/// Unit, finite normals; and the vertex normals agree with the winding: the geometric normal of each
/// (non-sliver) triangle points to the same side as its vertex normals. Returns the disagreeing share.
double checkNormals(const Mesh& m, const std::string& what) {
    EXPECT_EQ(m.normals.size(), m.positions.size()) << what;
    for (size_t i = 0; i < m.normals.size(); ++i) {
        const glm::vec3& n = m.normals[i];
        EXPECT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z))
            << what << " vertex " << i;
        EXPECT_NEAR(glm::length(n), 1.0f, 1e-4f) << what << " vertex " << i; // float normalisation
        EXPECT_TRUE(std::isfinite(m.positions[i].x + m.positions[i].y + m.positions[i].z)) << what;
    }
    size_t disagree = 0, counted = 0;
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        const uint32_t i0 = m.indices[3 * t], i1 = m.indices[3 * t + 1], i2 = m.indices[3 * t + 2];
        EXPECT_LT(std::max({i0, i1, i2}), m.vertexCount()) << what;
        const glm::vec3 g = glm::cross(m.positions[i1] - m.positions[i0], m.positions[i2] - m.positions[i0]);
        if (glm::length(g) < 1e-8f) continue; // collapsed pole triangles of the teapot patches
        ++counted;
        if (glm::dot(g, m.normals[i0] + m.normals[i1] + m.normals[i2]) <= 0.0f) ++disagree;
    }
    return counted ? double(disagree) / double(counted) : 0.0;
}

std::string teapotFile() {
    const std::string path = Paths::findResource("scenes/data/teapot.bpt");
    EXPECT_FALSE(path.empty()) << "scenes/data/teapot.bpt not found";
    return path;
}

} // namespace

TEST(MeshGeneratorsTest, SphereCountsClosednessAndVolume) {
    for (int tess : {3, 8, 16, 32}) {
        const Mesh m = MeshGenerators::sphere(tess);
        // (tess+1) rings of 2*tess+1 vertices (seam duplicated); 2*tess segments * (tess-1) quads,
        // the pole quads being single triangles: 4 * tess * (tess - 1) triangles.
        EXPECT_EQ(m.vertexCount(), size_t((tess + 1) * (2 * tess + 1)));
        EXPECT_EQ(m.triangleCount(), size_t(4 * tess * (tess - 1)));
        expectClosed(m, wholeMesh(m), "sphere");
        EXPECT_EQ(checkNormals(m, "sphere"), 0.0);
        // The inscribed polyhedron loses volume ~ the squared angular step: the sagitta 1 - cos(a/2)
        // ~ a^2/8 in each of two directions, so the deficit is below (pi/tess)^2 of the volume.
        const double exact = 4.0 / 3.0 * glm::pi<double>();
        const double v = signedVolume(m, wholeMesh(m));
        EXPECT_GT(v, 0.0);
        EXPECT_LE(v, exact);
        EXPECT_NEAR(v, exact, exact * std::pow(glm::pi<double>() / tess, 2.0)) << "tess " << tess;
        for (const auto& p : m.positions) EXPECT_NEAR(glm::length(p), 1.0f, 1e-5f);
    }
}

TEST(MeshGeneratorsTest, BoxCountsClosednessAndExactVolume) {
    const glm::vec3 half(1.0f, 0.5f, 2.0f);
    for (int tess : {1, 2, 5}) {
        const Mesh m = MeshGenerators::box(half, tess);
        EXPECT_EQ(m.vertexCount(), size_t(6 * (tess + 1) * (tess + 1)));
        EXPECT_EQ(m.triangleCount(), size_t(12 * tess * tess));
        expectClosed(m, wholeMesh(m), "box");
        EXPECT_EQ(checkNormals(m, "box"), 0.0);
        // Flat faces: the volume is exact up to float rounding of the corner coordinates.
        EXPECT_NEAR(signedVolume(m, wholeMesh(m)), 8.0 * half.x * half.y * half.z, 1e-4);
        const Aabb b = m.computeBounds();
        EXPECT_EQ(b.max, half);
        EXPECT_EQ(b.min, -half);
    }
}

TEST(MeshGeneratorsTest, CylinderCountsClosednessAndPrismVolume) {
    for (int tess : {2, 8, 16}) {
        const Mesh m = MeshGenerators::cylinder(tess);
        const int seg = 2 * tess;
        // Side grid (tess+1) x (seg+1), two caps of a centre and seg ring vertices.
        EXPECT_EQ(m.vertexCount(), size_t((tess + 1) * (seg + 1) + 2 * (seg + 1)));
        EXPECT_EQ(m.triangleCount(), size_t(2 * tess * seg + 2 * seg));
        expectClosed(m, wholeMesh(m), "cylinder");
        EXPECT_EQ(checkNormals(m, "cylinder"), 0.0);
        // The mesh is exactly the prism over the inscribed regular seg-gon: area (n/2) sin(2 pi / n),
        // height 2. Independent closed form, so only float rounding is left.
        const double prism = 2.0 * (seg / 2.0) * std::sin(2.0 * glm::pi<double>() / seg);
        EXPECT_NEAR(signedVolume(m, wholeMesh(m)), prism, 1e-5 * prism);
        const Aabb b = m.computeBounds();
        EXPECT_FLOAT_EQ(b.min.y, -1.0f);
        EXPECT_FLOAT_EQ(b.max.y, 1.0f);
    }
}

TEST(MeshGeneratorsTest, PlaneCountsAndFacesUp) {
    for (int tess : {1, 4, 16}) {
        const Mesh m = MeshGenerators::plane(10.0f, tess);
        EXPECT_EQ(m.vertexCount(), size_t((tess + 1) * (tess + 1)));
        EXPECT_EQ(m.triangleCount(), size_t(2 * tess * tess));
        EXPECT_EQ(checkNormals(m, "plane"), 0.0);
        for (const auto& n : m.normals) EXPECT_EQ(n, glm::vec3(0, 1, 0));
        double area = 0.0; // signed area seen from +Y: the total must be +size^2 (all CCW from above)
        for (size_t t = 0; t < m.triangleCount(); ++t) {
            const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                            c = m.positions[m.indices[3 * t + 2]];
            area += 0.5 * glm::cross(b - a, c - a).y;
        }
        EXPECT_NEAR(area, 100.0, 1e-3);
        const Aabb bounds = m.computeBounds();
        EXPECT_FLOAT_EQ(bounds.min.x, -5.0f);
        EXPECT_FLOAT_EQ(bounds.max.z, 5.0f);
        EXPECT_FLOAT_EQ(bounds.max.y, 0.0f);
    }
}

TEST(MeshGeneratorsTest, AircraftHasItsPartsClosedAndOutward) {
    const Mesh m = MeshGenerators::aircraft(16);
    // The brief: roughly 2k-6k triangles at the default tessellation 16.
    EXPECT_GE(m.triangleCount(), 2000u);
    EXPECT_LE(m.triangleCount(), 6000u);
    EXPECT_EQ(checkNormals(m, "aircraft"), 0.0);
    size_t covered = 0;
    for (const char* part : {"fuselage", "wings", "stabilisers", "fin_left", "fin_right"}) {
        const Range r = partRange(m, part);
        EXPECT_GT(r.triangleCount, 0u) << part;
        covered += r.triangleCount;
        expectClosed(m, r, part);
        EXPECT_GT(signedVolume(m, r), 0.0) << part << " wound inward";
    }
    EXPECT_EQ(covered, m.triangleCount());
    expectClosed(m, wholeMesh(m), "aircraft");
    // Length ~2 along X with the nose (the fuselage's pointed end) at +X; wingspan ~1.4.
    const Aabb b = m.computeBounds();
    EXPECT_NEAR(b.max.x - b.min.x, 2.0f, 0.2f);
    EXPECT_NEAR(b.max.x, 1.0f, 0.05f);
    EXPECT_NEAR(b.max.z - b.min.z, 1.4f, 0.1f);
    // The fuselage fits in the cylinder around its largest cross-section (width 0.286, height 0.22):
    // a loose, independent upper bound pi * a * b * length.
    const double fuselage = signedVolume(m, partRange(m, "fuselage"));
    EXPECT_LT(fuselage, glm::pi<double>() * 0.143 * 0.11 * 2.0);
}

TEST(MeshGeneratorsTest, AircraftWingsAndStabilisersLieInTheHorizontalPlane) {
    const Mesh m = MeshGenerators::aircraft(16);
    // Slabs 0.02 of the wingspan thick, centred on y = 0.
    const float halfThickness = 0.5f * 0.02f * 1.4f + 1e-6f;
    for (const char* part : {"wings", "stabilisers"}) {
        const Range r = partRange(m, part);
        for (size_t i = 3 * r.firstTriangle; i < 3 * (r.firstTriangle + r.triangleCount); ++i)
            EXPECT_LE(std::abs(m.positions[m.indices[i]].y), halfThickness) << part;
    }
}

TEST(MeshGeneratorsTest, AircraftFinsAreCantedOutwardAtTheRear) {
    const Mesh m = MeshGenerators::aircraft(16);
    for (const auto& [part, side] : {std::pair<const char*, float>{"fin_left", -1.0f}, {"fin_right", 1.0f}}) {
        const Range r = partRange(m, part);
        glm::vec3 lowest(0, 1e9f, 0), highest(0, -1e9f, 0);
        float maxX = -1e9f;
        // The normal of the largest face is the fin plane's normal: its tilt from horizontal is the cant.
        glm::vec3 faceNormal(0.0f);
        float largest = 0.0f;
        for (size_t t = r.firstTriangle; t < r.firstTriangle + r.triangleCount; ++t) {
            const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                            c = m.positions[m.indices[3 * t + 2]];
            for (const auto& p : {a, b, c}) {
                if (p.y < lowest.y) lowest = p;
                if (p.y > highest.y) highest = p;
                maxX = std::max(maxX, p.x);
            }
            const glm::vec3 g = glm::cross(b - a, c - a);
            if (glm::length(g) > largest) largest = glm::length(g), faceNormal = glm::normalize(g);
        }
        EXPECT_LT(maxX, -0.3f) << part << " not at the rear";
        EXPECT_GT(side * (highest.z - lowest.z), 0.0f) << part << " not canted outward";
        EXPECT_NEAR(std::abs(faceNormal.y), std::sin(glm::radians(25.0f)), 1e-3f) << part;
        EXPECT_NEAR(faceNormal.x, 0.0f, 1e-4f) << part;
    }
}

TEST(MeshGeneratorsTest, AircraftTessellationKnobScalesTheCurvedParts) {
    const Mesh lo = MeshGenerators::aircraft(8), hi = MeshGenerators::aircraft(16);
    const double ratio =
        double(partRange(hi, "fuselage").triangleCount) / partRange(lo, "fuselage").triangleCount;
    EXPECT_DOUBLE_EQ(ratio, 4.0); // rings and segments both double
    EXPECT_GT(hi.triangleCount(), 3 * lo.triangleCount());
}

TEST(MeshGeneratorsTest, TeapotCountsPartsAndPlacement) {
    const std::string file = teapotFile();
    for (int tess : {1, 4, 8, 16}) {
        const Mesh m = MeshGenerators::teapot(file, tess);
        EXPECT_EQ(m.vertexCount(), size_t(32 * (tess + 1) * (tess + 1)));
        EXPECT_EQ(m.triangleCount(), size_t(32 * tess * tess * 2));
        // Winding and normals agree except on a few slivers next to the collapsed poles, whose
        // float positions differ by rounding only. At tess 1 a single quad spans a whole half-tube
        // of the handle, so its chord can face away from the corner normals: not checked there.
        const double disagree = checkNormals(m, "teapot");
        if (tess >= 4) {
            EXPECT_LT(disagree, 0.005) << "tess " << tess;
        }
        const char* names[] = {"rim", "body", "handle", "spout", "lid", "bottom"};
        const int patches[] = {4, 8, 4, 4, 8, 4};
        ASSERT_EQ(m.parts.size(), 6u);
        uint32_t next = 0;
        for (int i = 0; i < 6; ++i) {
            EXPECT_EQ(m.parts[size_t(i)].name, names[i]);
            EXPECT_EQ(m.parts[size_t(i)].firstIndex, next);
            EXPECT_EQ(m.parts[size_t(i)].indexCount, uint32_t(patches[i] * tess * tess * 6));
            next += m.parts[size_t(i)].indexCount;
        }
        // Y-up, standing on y = 0: the data's z range 0..3.15 becomes y; the spout (+x) tip reaches
        // x = 3.3 at the end of the curve (its middle control points go to 3.525), the handle x = -3.
        const Aabb b = m.computeBounds();
        EXPECT_NEAR(b.min.y, 0.0f, 1e-6f);
        EXPECT_NEAR(b.max.y, 3.15f, 1e-5f);
        EXPECT_NEAR(b.min.x, -3.0f, 1e-5f);
        EXPECT_GE(b.max.x, 3.3f - 1e-5f);
    }
}

TEST(MeshGeneratorsTest, TeapotNormalsPointOutOfTheBody) {
    const Mesh m = MeshGenerators::teapot(teapotFile(), 8);
    const MeshPart& body = m.parts[1];
    for (uint32_t i = body.firstIndex; i < body.firstIndex + body.indexCount; ++i) {
        const glm::vec3 p = m.positions[m.indices[i]], n = m.normals[m.indices[i]];
        EXPECT_GT(glm::dot(n, glm::vec3(p.x, 0, p.z)), 0.0f) << "body normal points inward";
    }
    const MeshPart& bottom = m.parts[5];
    // The bottom curves up into the body: its outer border is vertical (normal.y = 0), never upward.
    for (uint32_t i = bottom.firstIndex; i < bottom.firstIndex + bottom.indexCount; ++i)
        EXPECT_LE(m.normals[m.indices[i]].y, 1e-6f) << "bottom normal points up";
    EXPECT_NEAR(m.normals[m.indices[bottom.firstIndex]].y, -1.0f, 1e-3f) << "bottom centre (the pole)";
}

TEST(MeshGeneratorsTest, TeapotBodyAndBottomPatchBordersMeet) {
    // Vertices of patch p are the (tess+1)^2 consecutive vertices from p*(tess+1)^2 (row-major).
    // Every border vertex of the body and bottom patches lies on a neighbouring patch's border
    // (rim above, bottom below, the next patch around): the patches share their control points there,
    // so only evaluation rounding separates them (1e-5 at coordinates ~2).
    const int tess = 6, n = tess + 1;
    const Mesh m = MeshGenerators::teapot(teapotFile(), tess);
    auto patchOf = [&](size_t v) { return int(v / size_t(n * n)); };
    for (int p : {4, 5, 6, 7, 8, 9, 10, 11, 28, 29, 30, 31}) {
        for (int r = 0; r < n; ++r) {
            for (int c = 0; c < n; ++c) {
                if (r != 0 && c != 0 && r != tess && c != tess) continue;
                const glm::vec3 q = m.positions[size_t(p * n * n + r * n + c)];
                bool shared = false;
                for (size_t v = 0; v < m.vertexCount() && !shared; ++v)
                    shared = patchOf(v) != p && glm::length(m.positions[v] - q) < 1e-5f;
                EXPECT_TRUE(shared) << "patch " << p << " border vertex " << r << "," << c;
            }
        }
    }
}

TEST(MeshGeneratorsTest, TessellationOutOfRangeIsAnError) {
    EXPECT_THROW(MeshGenerators::sphere(2), std::runtime_error);
    EXPECT_THROW(MeshGenerators::box(glm::vec3(1), 0), std::runtime_error);
    EXPECT_THROW(MeshGenerators::teapot("/nonexistent/teapot.bpt", 4), std::runtime_error);
}

namespace {

/// Union-find over vertex representatives, for counting connected pieces.
struct Components {
    std::vector<uint32_t> parent;
    explicit Components(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
    uint32_t find(uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    }
    void unite(uint32_t a, uint32_t b) { parent[find(a)] = find(b); }
};

/// V - E + F of the welded triangles of `r`: V counts the welded vertices the triangles use, E the
/// undirected welded edges.
long eulerCharacteristic(const Mesh& m, Range r) {
    const auto rep = weld(m.positions);
    std::set<uint32_t> vertices;
    std::set<std::pair<uint32_t, uint32_t>> edges;
    for (size_t t = r.firstTriangle; t < r.firstTriangle + r.triangleCount; ++t) {
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = rep[m.indices[3 * t + size_t(k)]],
                           b = rep[m.indices[3 * t + size_t(k + 1) % 3]];
            vertices.insert(a);
            edges.insert({std::min(a, b), std::max(a, b)});
        }
    }
    return long(vertices.size()) - long(edges.size()) + long(r.triangleCount);
}

/// Signed solid angle of the triangle a, b, c of unit vectors seen from the centre (Van Oosterom and
/// Strackee 1983): positive when a, b, c run counter-clockwise seen from outside.
double solidAngle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    return 2.0 *
           std::atan2(glm::dot(a, glm::cross(b, c)), 1.0 + glm::dot(a, b) + glm::dot(b, c) + glm::dot(c, a));
}

/// A hole of the lantern as seen on its outer sphere: the loop of tunnel wall edges with both ends at
/// radius 1, its centre direction and its solid angle (of the spherical polygon of great-circle arcs
/// that the loop's chords project to).
struct HoleLoop {
    glm::dvec3 centre;
    double omega;
};
std::vector<HoleLoop> lanternHoleLoops(const Mesh& m) {
    const auto rep = weld(m.positions);
    const Range walls = partRange(m, "holes");
    std::vector<std::pair<uint32_t, uint32_t>> rim; // directed outer edges of the walls
    for (size_t t = walls.firstTriangle; t < walls.firstTriangle + walls.triangleCount; ++t) {
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = m.indices[3 * t + size_t(k)], b = m.indices[3 * t + size_t(k + 1) % 3];
            if (std::abs(glm::length(m.positions[a]) - 1.0f) < 1e-5f &&
                std::abs(glm::length(m.positions[b]) - 1.0f) < 1e-5f)
                rim.push_back({rep[a], rep[b]});
        }
    }
    Components pieces(m.vertexCount());
    for (const auto& [a, b] : rim) pieces.unite(a, b);
    std::map<uint32_t, std::vector<std::pair<uint32_t, uint32_t>>> loops;
    for (const auto& e : rim) loops[pieces.find(e.first)].push_back(e);
    std::vector<HoleLoop> holes;
    for (const auto& [root, loop] : loops) {
        glm::dvec3 centre(0.0);
        for (const auto& [a, b] : loop) centre += glm::dvec3(m.positions[a]);
        centre = glm::normalize(centre);
        double omega = 0.0; // fan from the loop's centre direction; the walls run v -> u, around the hole
        for (const auto& [a, b] : loop)
            omega += solidAngle(centre, glm::dvec3(m.positions[a]), glm::dvec3(m.positions[b]));
        holes.push_back({centre, omega});
    }
    return holes;
}

} // namespace

TEST(MeshGeneratorsTest, LanternIsClosedWithFourTunnelsAndGenusThree) {
    // 8..12 are the tessellations where the holes are one or two cells and could touch; the
    // generator checks that they do not (and throws), these check the result.
    for (int tess : {8, 9, 10, 11, 12, 16, 24, 32, 48}) {
        const Mesh m = MeshGenerators::lantern(0.08f, tess);
        const std::string what = "lantern " + std::to_string(tess);
        expectClosed(m, wholeMesh(m), what);
        EXPECT_EQ(checkNormals(m, what), 0.0);
        ASSERT_EQ(m.parts.size(), 2u);
        EXPECT_EQ(m.parts[0].name, "shell");
        EXPECT_EQ(m.parts[1].name, "holes");
        EXPECT_EQ(m.parts[0].indexCount + m.parts[1].indexCount, m.indices.size());
        // The grid vertices inside the holes are dropped: every vertex is used.
        std::vector<bool> referenced(m.vertexCount(), false);
        for (uint32_t i : m.indices) referenced[i] = true;
        EXPECT_EQ(std::count(referenced.begin(), referenced.end(), false), 0) << what;
        // The tunnel walls form one closed band per hole: four connected pieces.
        const auto rep = weld(m.positions);
        const Range walls = partRange(m, "holes");
        Components pieces(m.vertexCount());
        std::set<uint32_t> used;
        for (size_t t = walls.firstTriangle; t < walls.firstTriangle + walls.triangleCount; ++t)
            for (int k = 0; k < 3; ++k) {
                pieces.unite(rep[m.indices[3 * t + size_t(k)]], rep[m.indices[3 * t + size_t(k + 1) % 3]]);
                used.insert(rep[m.indices[3 * t + size_t(k)]]);
            }
        std::set<uint32_t> roots;
        for (uint32_t v : used) roots.insert(pieces.find(v));
        const long holes = long(roots.size());
        EXPECT_EQ(holes, 4) << what;
        // Euler characteristic. The outer and the inner sphere grids are spheres (chi = 2 each). A hole
        // removes an open disc of cells from each (chi 2 -> 1: the disc's V - E + F is 1) and adds its
        // wall: b quads along the b border edges of the disc, adding b radial edges, b diagonals and 2b
        // triangles but no vertex (b - b - b + 2b... i.e. -2b + 2b = 0). So chi = 2 * (2 - h) = 4 - 2h,
        // which for a connected closed orientable surface is 2 - 2g: genus g = h - 1 = 3 (one hole
        // turns the shell into a thick bowl, a sphere; each further one adds a handle). Not 2 - 2h: the
        // brief's formula would count the shell itself as a handle.
        EXPECT_EQ(eulerCharacteristic(m, wholeMesh(m)), 4 - 2 * holes) << what;
        EXPECT_EQ(eulerCharacteristic(m, wholeMesh(m)), -4) << what;
    }
}

TEST(MeshGeneratorsTest, LanternShellsFaceAwayFromTheSolid) {
    const float thickness = 0.08f;
    const Mesh m = MeshGenerators::lantern(thickness, 32);
    const Range shell = partRange(m, "shell");
    size_t outer = 0, inner = 0;
    for (size_t t = shell.firstTriangle; t < shell.firstTriangle + shell.triangleCount; ++t) {
        const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                        c = m.positions[m.indices[3 * t + 2]];
        const glm::vec3 g = glm::cross(b - a, c - a), centroid = (a + b + c) / 3.0f;
        const float radius = glm::length(a);
        ASSERT_NEAR(glm::length(b), radius, 1e-5f);
        ASSERT_NEAR(glm::length(c), radius, 1e-5f);
        if (std::abs(radius - 1.0f) < 1e-5f) {
            ++outer;
            EXPECT_GT(glm::dot(g, centroid), 0.0f) << "outer triangle " << t << " faces the centre";
        } else {
            EXPECT_NEAR(radius, 1.0f - thickness, 1e-5f);
            ++inner;
            EXPECT_LT(glm::dot(g, centroid), 0.0f) << "inner triangle " << t << " faces away from the centre";
        }
    }
    EXPECT_EQ(outer, inner); // the same cells are cut from both
    EXPECT_GT(outer, 0u);
    // The tunnel walls are radial: each quad lies in a plane through the centre.
    const Range walls = partRange(m, "holes");
    EXPECT_GT(walls.triangleCount, 0u);
    for (size_t t = walls.firstTriangle; t < walls.firstTriangle + walls.triangleCount; ++t) {
        const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                        c = m.positions[m.indices[3 * t + 2]];
        const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
        EXPECT_NEAR(glm::dot(n, glm::normalize(a + b + c)), 0.0f, 1e-4f) << "wall triangle " << t;
    }
}

TEST(MeshGeneratorsTest, LanternVolumeIsTheShellLessItsTunnels) {
    const double pi = glm::pi<double>();
    const double k = 1.0 - 0.08; // inner radius (the outer one is 1)
    for (int tess : {16, 32, 64}) {
        const Mesh m = MeshGenerators::lantern(0.08f, tess);
        // The tunnels: radial prisms between the two spheres through the holes' border loops; a
        // solid angle omega of it holds omega * (1 - k^3) / 3.
        const std::vector<HoleLoop> holes = lanternHoleLoops(m);
        ASSERT_EQ(holes.size(), 4u);
        double omegaHoles = 0.0;
        for (const HoleLoop& h : holes) {
            EXPECT_GT(h.omega, 0.0) << "tess " << tess; // the loops run around their holes consistently
            omegaHoles += h.omega;
        }
        const double tunnels = omegaHoles * (1.0 - k * k * k) / 3.0;
        const double ideal = 4.0 / 3.0 * pi * (1.0 - k * k * k) - tunnels;
        // The mesh is that ideal shell with its spherical surfaces replaced by the chords of the sphere
        // grid. The walls are planar through the centre, so they add nothing to the divergence sum, and
        // each outer triangle's tetrahedron to the centre is smaller than the cone of its solid angle
        // (the triangle lies inside the unit sphere), the inner ones scaled by k. So the mesh loses
        // (1 - k^3) times the cone-minus-tetrahedron deficits of the kept cells: at most (1 - k^3)
        // times the deficit of the whole sphere(tess), which shares the grid.
        const Mesh sphere = MeshGenerators::sphere(tess);
        const double sphereDeficit = 4.0 / 3.0 * pi - signedVolume(sphere, wholeMesh(sphere));
        const double v = signedVolume(m, wholeMesh(m));
        EXPECT_NEAR(signedVolume(m, partRange(m, "holes")), 0.0, 1e-6) << "tess " << tess;
        EXPECT_LE(v, ideal + 1e-6) << "tess " << tess;
        EXPECT_GE(v, ideal - (1.0 - k * k * k) * sphereDeficit - 1e-6) << "tess " << tess;
        // The holes themselves: about 12% of the sphere, the mouth and the eyes on the +Z side, the
        // bottom one around -Y: the rows whose centres lie more than 62 degrees below the equator, so its
        // rim is a ring within half a row of 28 degrees from -Y, the polygon of its 2 * tess chords a
        // little smaller than that ring's cap.
        EXPECT_GT(omegaHoles, 0.08 * 4.0 * pi) << "tess " << tess;
        EXPECT_LT(omegaHoles, 0.16 * 4.0 * pi) << "tess " << tess;
        const double halfRow = 0.5 * pi / tess, cap = 28.0 * pi / 180.0;
        int front = 0, bottom = 0;
        for (const HoleLoop& h : holes) {
            if (h.centre.y < -0.999) {
                ++bottom;
                EXPECT_LT(h.omega, 2.0 * pi * (1.0 - std::cos(cap + halfRow))) << "tess " << tess;
                EXPECT_GT(h.omega, 0.95 * 2.0 * pi * (1.0 - std::cos(cap - halfRow))) << "tess " << tess;
            } else if (h.centre.z > 0.7) {
                ++front;
            }
        }
        EXPECT_EQ(bottom, 1) << "tess " << tess;
        EXPECT_EQ(front, 3) << "tess " << tess;
    }
}

TEST(MeshGeneratorsTest, LanternHolesStayApartAtEveryTessellation) {
    // The generator throws where its holes would touch or miss; from 12 on the gaps between the
    // outlines (20 degrees of latitude, 32 of longitude) exceed one and two cells, the widening of a
    // row by a cell included, so checking up to 128 covers every coarse case.
    for (int tess = MeshGenerators::kLanternMinimumTessellation; tess <= 128; ++tess)
        EXPECT_NO_THROW(MeshGenerators::lantern(0.08f, tess)) << "tess " << tess;
    EXPECT_THROW(MeshGenerators::lantern(0.08f, 7), std::runtime_error);
    EXPECT_THROW(MeshGenerators::lantern(0.0f, 16), std::runtime_error);
    EXPECT_THROW(MeshGenerators::lantern(1.0f, 16), std::runtime_error);
}
