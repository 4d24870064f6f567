#include "techniques/volume/ShadowVolumeMesh.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

#include "core/Error.h"

namespace sb {

namespace {

/// Integer coordinates of a cell of the welding grid.
struct Cell {
    int64_t x = 0, y = 0, z = 0;
    bool operator==(const Cell&) const = default;
};

struct CellHash {
    size_t operator()(const Cell& c) const {
        // Large odd multipliers (as in spatial hashing, Teschner et al. 2003) spread neighbouring cells.
        return size_t(uint64_t(c.x) * 73856093u ^ uint64_t(c.y) * 19349663u ^ uint64_t(c.z) * 83492791u);
    }
};

/// The welding grid: cells of the weld distance, each holding a chain of the welded vertices that fell
/// in it. Two points within the distance are at most one cell apart on every axis, so looking at the 27
/// cells around a point finds every candidate, wherever the cell borders fall (rounding to a grid
/// alone would split pairs that straddle a border).
class WeldGrid {
public:
    WeldGrid(float distance, size_t expected) : mDistance(distance) {
        // Distance 0 (a point-like mesh, or welding switched off): exact matches only, any cell size.
        mInvCell = distance > 0.0f ? 1.0 / double(distance) : 1.0;
        mHeads.reserve(expected);
        mNext.reserve(expected);
    }

    /// The welded vertex within the distance of `p`, or kNone.
    uint32_t find(const glm::vec3& p, const std::vector<glm::vec3>& welded) const {
        const Cell c = cellOf(p);
        for (int64_t dz = -1; dz <= 1; ++dz)
            for (int64_t dy = -1; dy <= 1; ++dy)
                for (int64_t dx = -1; dx <= 1; ++dx) {
                    const auto it = mHeads.find({c.x + dx, c.y + dy, c.z + dz});
                    if (it == mHeads.end()) continue;
                    for (uint32_t v = it->second; v != kNone; v = mNext[v])
                        if (glm::length(welded[v] - p) <= mDistance) return v;
                }
        return kNone;
    }

    /// Registers welded vertex `v` (numbered in insertion order) at `p`.
    void insert(uint32_t v, const glm::vec3& p) {
        auto [it, added] = mHeads.try_emplace(cellOf(p), v);
        mNext.push_back(added ? kNone : it->second);
        it->second = v;
    }

    static constexpr uint32_t kNone = 0xffffffffu;

private:
    Cell cellOf(const glm::vec3& p) const {
        return {int64_t(std::floor(double(p.x) * mInvCell)), int64_t(std::floor(double(p.y) * mInvCell)),
                int64_t(std::floor(double(p.z) * mInvCell))};
    }

    float mDistance;
    double mInvCell;
    std::unordered_map<Cell, uint32_t, CellHash> mHeads;
    std::vector<uint32_t> mNext; ///< per welded vertex: the next one in its cell
};

using Edge = ShadowVolumeMesh::Edge;
constexpr uint32_t kNoFace = ShadowVolumeMesh::kNoFace;
constexpr uint32_t kReversed = ShadowVolumeMesh::kReversed;

uint64_t edgeKey(uint32_t a, uint32_t b) {
    return (uint64_t(std::min(a, b)) << 32) | uint64_t(std::max(a, b));
}

/// Appends the triangle a, b, c, each index offset by `offset` (n for the w = 0 copies).
void pushTriangle(std::vector<uint32_t>& out, uint32_t a, uint32_t b, uint32_t c, uint32_t offset = 0) {
    out.push_back(a + offset);
    out.push_back(b + offset);
    out.push_back(c + offset);
}

/// The side of a silhouette edge directed a -> b (the direction of the light-back face, Listing 9-7):
/// the quad a, b, b', a' between the edge and its image at infinity, as two triangles; or, for the
/// directional form (section 9.5.1), one triangle converging on the single point at infinity (any
/// w = 0 vertex stands for it: n).
void pushSide(std::vector<uint32_t>& out, uint32_t a, uint32_t b, uint32_t n, bool directional) {
    if (directional) {
        pushTriangle(out, a, b, n);
        return;
    }
    pushTriangle(out, a, b, b + n);
    pushTriangle(out, a, b + n, a + n);
}

/// One record per undirected edge of `faces` (3 welded indices each) and the 3 directed edges of every
/// face as edge index | kReversed; returns the number of open edges.
size_t buildEdges(const std::vector<uint32_t>& faces, std::vector<Edge>& edges,
                  std::vector<uint32_t>& faceEdges) {
    // Sort the 3F directed face edges by their undirected key: each run of equal keys is one edge.
    // Sorting rather than hashing keeps the edge order deterministic (by vertex pair).
    const size_t slots = faces.size();
    std::vector<uint64_t> keys(slots);
    for (size_t s = 0; s < slots; ++s) keys[s] = edgeKey(faces[s], faces[s - s % 3 + (s + 1) % 3]);
    std::vector<uint32_t> order(slots);
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return keys[a] < keys[b]; });

    faceEdges.assign(slots, 0);
    edges.clear();
    size_t open = 0;
    for (size_t i = 0; i < slots;) {
        size_t end = i;
        while (end < slots && keys[order[end]] == keys[order[i]]) ++end;
        // v0 < v1 always: then face0 is the first face traversing low -> high, face1 the first one
        // traversing high -> low, which is the chapter's convention (and v0 < v1 when face0 is absent).
        Edge e;
        e.v0 = uint32_t(keys[order[i]] >> 32);
        e.v1 = uint32_t(keys[order[i]]);
        const uint32_t index = uint32_t(edges.size());
        int forward = 0, backward = 0;
        for (size_t j = i; j < end; ++j) {
            const uint32_t s = order[j], face = s / 3;
            const bool reversed = faces[s] != e.v0; // the slot's edge starts at its own vertex
            faceEdges[s] = index | (reversed ? kReversed : 0u);
            if (reversed) {
                if (backward++ == 0) e.face1 = face;
            } else if (forward++ == 0) {
                e.face0 = face;
            }
        }
        // Closed: exactly one face each way. A crack has one face; two faces wound alike, or more than
        // two faces, make a non-manifold edge: open too, as the Closed policy cannot handle either.
        if (forward != 1 || backward != 1) ++open;
        edges.push_back(e);
        i = end;
    }
    return open;
}

} // namespace

ShadowVolumeMesh::ShadowVolumeMesh(const Mesh& mesh, float weldTolerance) : mName(mesh.name) {
    const size_t inputVertices = mesh.positions.size();
    for (size_t i = 0; i < inputVertices; ++i) {
        const glm::vec3& p = mesh.positions[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw Error("shadow volume mesh '" + mName + "': vertex " + std::to_string(i) +
                        " has a non-finite position");
    }

    // Welding (section 9.2.2): normals and texture coordinates are irrelevant for adjacency, only
    // positions count, so seam duplicates become one vertex.
    const Aabb bounds = mesh.computeBounds();
    const glm::vec3 extent = bounds.empty() ? glm::vec3(0.0f) : bounds.extent();
    const float distance = std::max(0.0f, weldTolerance) * std::max({extent.x, extent.y, extent.z});
    WeldGrid grid(distance, inputVertices);
    std::vector<uint32_t> remap(inputVertices);
    mPositions.reserve(inputVertices);
    for (size_t i = 0; i < inputVertices; ++i) {
        const glm::vec3& p = mesh.positions[i];
        uint32_t v = grid.find(p, mPositions);
        if (v == WeldGrid::kNone) {
            v = uint32_t(mPositions.size());
            mPositions.push_back(p);
            grid.insert(v, p);
        }
        remap[i] = v;
    }
    mWeldedAway = inputVertices - mPositions.size();

    // Faces: welded indices; faces that welding collapsed have no area and no edges of their own.
    const size_t triangles = mesh.triangleCount();
    mFaces.reserve(3 * triangles);
    for (size_t t = 0; t < triangles; ++t) {
        uint32_t v[3];
        for (int k = 0; k < 3; ++k) {
            const uint32_t index = mesh.indices[3 * t + size_t(k)];
            if (index >= inputVertices)
                throw Error("shadow volume mesh '" + mName + "': triangle " + std::to_string(t) +
                            " uses vertex " + std::to_string(index) + " of " + std::to_string(inputVertices));
            v[k] = remap[index];
        }
        if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) {
            ++mCollapsedFaces;
            continue;
        }
        mFaces.insert(mFaces.end(), v, v + 3);
    }
    mFaceNormals.resize(faceCount());
    for (size_t f = 0; f < faceCount(); ++f) {
        const glm::vec3& p0 = mPositions[mFaces[3 * f]];
        // Unnormalised: only the sign of N.L is ever used (Listing 9-5).
        mFaceNormals[f] = glm::cross(mPositions[mFaces[3 * f + 1]] - p0, mPositions[mFaces[3 * f + 2]] - p0);
    }
    mOpenEdges = buildEdges(mFaces, mEdges, mFaceEdges);
}

std::vector<glm::vec4> ShadowVolumeMesh::doubledVertices() const {
    std::vector<glm::vec4> out;
    out.reserve(2 * mPositions.size());
    for (const glm::vec3& p : mPositions) out.emplace_back(p, 1.0f);
    for (const glm::vec3& p : mPositions) out.emplace_back(p, 0.0f);
    return out;
}

std::vector<uint32_t> ShadowVolumeMesh::neighbours() const {
    std::vector<uint32_t> out(mFaceEdges.size(), kNoFace);
    for (size_t s = 0; s < mFaceEdges.size(); ++s) {
        const Edge& e = mEdges[mFaceEdges[s] & ~kReversed];
        // A face traversing v1 -> v0 faces face0 across the edge, one traversing v0 -> v1 face1. On an
        // open edge (one face, or more than two) the partner may be missing or the face itself.
        const uint32_t other = (mFaceEdges[s] & kReversed) ? e.face0 : e.face1;
        out[s] = other == uint32_t(s / 3) ? kNoFace : other;
    }
    return out;
}

void ShadowVolumeMesh::classifyFaces(const glm::vec4& light, std::vector<uint8_t>& out) const {
    out.resize(faceCount());
    const glm::vec3 l(light);
    for (size_t f = 0; f < faceCount(); ++f) {
        // L.xyz - P0 * L.w: towards a point light from the face, or the directional light's vector.
        // A zero normal (sliver) gives 0: light-facing, so it stays in the light cap.
        out[f] = glm::dot(mFaceNormals[f], l - mPositions[mFaces[3 * f]] * light.w) < 0.0f;
    }
}

namespace {

/// What the caps and sides are built from: the welded faces, their classification and n.
struct VolumeSource {
    const std::vector<uint32_t>& faces;
    const std::vector<uint8_t>& backface;
    uint32_t n;
    size_t faceCount() const { return backface.size(); }
};

void buildClosedCaps(const VolumeSource& src, bool lightCap, bool darkCap, VolumeIndices& out) {
    // Listing 9-6: light-facing faces as they are; the others at infinity, same winding, which seen
    // from the light (a central projection keeps it) is clockwise: facing out of the volume's far end.
    for (size_t f = 0; f < src.faceCount(); ++f) {
        const uint32_t* v = &src.faces[3 * f];
        if (!src.backface[f]) {
            if (lightCap) pushTriangle(out.lightCap, v[0], v[1], v[2]);
        } else if (darkCap) {
            pushTriangle(out.darkCap, v[0], v[1], v[2], src.n);
        }
    }
}

void buildClosedSides(const VolumeSource& src, const std::vector<Edge>& edges, bool directional,
                      VolumeIndices& out) {
    // Listing 9-7: an edge between a light-back and a light-facing face is a silhouette; its side
    // contains the edge directed as the back face traverses it, so it runs opposite to the light cap
    // along the shared edge and the volume stays closed and outward-facing.
    for (const Edge& e : edges) {
        if (e.face0 == kNoFace || e.face1 == kNoFace) continue; // no side without two faces
        const bool back0 = src.backface[e.face0];
        if (back0 == bool(src.backface[e.face1])) continue;
        if (back0)
            pushSide(out.sides, e.v0, e.v1, src.n, directional);
        else
            pushSide(out.sides, e.v1, e.v0, src.n, directional);
        ++out.silhouetteEdges;
    }
}

void buildOrientedCaps(const VolumeSource& src, bool lightCap, bool darkCap, VolumeIndices& out) {
    // Every face is an occluder whichever side the light sees: a light-back face is flipped to face
    // the light. Light cap: all faces so oriented; dark cap: the same at infinity wound the other way
    // (facing away from the light), which for a back face is its original winding.
    for (size_t f = 0; f < src.faceCount(); ++f) {
        const uint32_t* v = &src.faces[3 * f];
        const bool back = src.backface[f];
        if (lightCap) {
            if (back)
                pushTriangle(out.lightCap, v[0], v[2], v[1]);
            else
                pushTriangle(out.lightCap, v[0], v[1], v[2]);
        }
        if (darkCap) {
            if (back)
                pushTriangle(out.darkCap, v[0], v[1], v[2], src.n);
            else
                pushTriangle(out.darkCap, v[0], v[2], v[1], src.n);
        }
    }
}

void buildMultiplicitySides(const VolumeSource& src, const std::vector<Edge>& edges,
                            const std::vector<uint32_t>& faceEdges, std::vector<int32_t>& multiplicity,
                            bool directional, VolumeIndices& out) {
    // m[e]: how many more oriented faces traverse e as v0 -> v1 than as v1 -> v0. The light cap's
    // boundary runs m times along v0 -> v1, so m sides containing v1 -> v0 close it (m < 0: |m| sides
    // containing v0 -> v1). For a closed mesh m is 0 on ordinary edges and -2 on a silhouette with a
    // back face0 (both faces then run v1 -> v0), +2 with a back face1: Closed's side, drawn twice.
    multiplicity.assign(edges.size(), 0);
    for (size_t f = 0; f < src.faceCount(); ++f) {
        const int32_t orientation = src.backface[f] ? -1 : 1;
        for (size_t k = 0; k < 3; ++k) {
            const uint32_t fe = faceEdges[3 * f + k];
            multiplicity[fe & ~kReversed] += (fe & kReversed) ? -orientation : orientation;
        }
    }
    for (size_t i = 0; i < edges.size(); ++i) {
        const int32_t m = multiplicity[i];
        if (m == 0) continue;
        const Edge& e = edges[i];
        const uint32_t a = m > 0 ? e.v1 : e.v0, b = m > 0 ? e.v0 : e.v1;
        for (int32_t copy = 0; copy < std::abs(m); ++copy) pushSide(out.sides, a, b, src.n, directional);
        ++out.silhouetteEdges;
    }
}

} // namespace

void ShadowVolumeMesh::buildVolume(const VolumeRequest& request, VolumeIndices& out) const {
    // clear() keeps the capacity: once the vectors have grown, a frame allocates nothing.
    out.lightCap.clear();
    out.darkCap.clear();
    out.sides.clear();
    out.silhouetteEdges = 0;
    // The directional form's sides close on the one point at infinity: no dark cap to draw.
    const bool directional = request.directionalForm && request.light.w == 0.0f;
    const bool lightCap = request.caps && request.lightCap;
    const bool darkCap = request.caps && request.darkCap && !directional;
    if (!lightCap && !darkCap && !request.sides) return;
    classifyFaces(request.light, mBackface);
    const VolumeSource src{mFaces, mBackface, vertexCount()};
    if (request.policy == OpenEdgePolicy::Closed) {
        buildClosedCaps(src, lightCap, darkCap, out);
        if (request.sides) buildClosedSides(src, mEdges, directional, out);
    } else {
        buildOrientedCaps(src, lightCap, darkCap, out);
        if (request.sides) buildMultiplicitySides(src, mEdges, mFaceEdges, mMultiplicity, directional, out);
    }
}

namespace {

/// Appends the McGuire-Hughes quad of one matched pair of half-edges: face A traverses p -> q, face B
/// q -> p. Vertices [q, p] carry A's plane and [p, q] B's: off the silhouette both pairs move together
/// and the quad stays degenerate; on it one pair goes to infinity and the quad opens into Listing
/// 9-7's side (with A back: (q', p', p, q), the cycle of the side (p, q, q', p')).
void pushEdgeQuad(ExtrusionMesh& m, const glm::vec3& p, const glm::vec3& q, const glm::vec4& planeA,
                  const glm::vec4& planeB) {
    const uint32_t first = uint32_t(m.positions.size());
    for (const glm::vec3& v : {q, p}) m.positions.push_back(v), m.facePlanes.push_back(planeA);
    for (const glm::vec3& v : {p, q}) m.positions.push_back(v), m.facePlanes.push_back(planeB);
    pushTriangle(m.sideIndices, first, first + 1, first + 2);
    pushTriangle(m.sideIndices, first, first + 2, first + 3);
}

} // namespace

glm::vec4 ShadowVolumeMesh::facePlane(size_t f) const {
    const glm::vec3& n = mFaceNormals[f];
    return {n, glm::dot(n, mPositions[mFaces[3 * f]])};
}

bool ShadowVolumeMesh::pairedInMesh(size_t face, size_t k) const {
    const uint32_t fe = mFaceEdges[3 * face + k];
    const Edge& e = mEdges[fe & ~kReversed];
    // A face traversing v0 -> v1 is matched when it is the edge's face0 and a face1 exists, and the
    // other way round; open edges and the extra faces of a non-manifold edge are unmatched.
    return (fe & kReversed) ? (e.face1 == face && e.face0 != kNoFace)
                            : (e.face0 == face && e.face1 != kNoFace);
}

ExtrusionMesh ShadowVolumeMesh::buildExtrusionMesh(OpenEdgePolicy policy) const {
    // McGuire and Hughes (2003): the shader extrudes a vertex iff the face it belongs to is light-back,
    // so each face needs its own 3 vertices (light cap or dark cap), and each edge a quad of two vertex
    // pairs carrying the two faces' planes. The classification uses the face plane (N, dot(N, P0)),
    // identical in every vertex of the face, so the vertices of one face can never disagree (per-vertex
    // dot(N, L - P) would, in float, when the light grazes the face: cracks).
    //
    // An open mesh under Multiplicity becomes a two-sheet closed surface: every face plus its twin
    // (reversed winding, negated plane), exactly one of which faces the light. Matched edges get a quad
    // on each sheet, every unmatched half-edge a quad between the face and its own twin, which is
    // always a silhouette: the crack's side. That is the thin solid the CPU's multiplicity volume
    // describes (count 2 behind a wall, like it), at twice the caps and sides of the closed path.
    const bool twoSheets = policy == OpenEdgePolicy::Multiplicity && !closed();
    const size_t sheets = twoSheets ? 2 : 1;
    ExtrusionMesh m;
    m.twoSheets = twoSheets;
    size_t matched = 0;
    for (const Edge& e : mEdges) matched += e.face0 != kNoFace && e.face1 != kNoFace;
    const size_t unmatched = twoSheets ? 3 * faceCount() - 2 * matched : 0;
    const size_t quads = sheets * matched + unmatched;
    m.positions.reserve(3 * sheets * faceCount() + 4 * quads);
    m.facePlanes.reserve(m.positions.capacity());
    m.capIndices.reserve(3 * sheets * faceCount());
    m.sideIndices.reserve(6 * quads);
    for (size_t sheet = 0; sheet < sheets; ++sheet)
        for (size_t f = 0; f < faceCount(); ++f) {
            const glm::vec4 plane = sheet ? -facePlane(f) : facePlane(f);
            const size_t order[2][3] = {{0, 1, 2}, {0, 2, 1}};
            for (size_t k : order[sheet]) {
                m.capIndices.push_back(uint32_t(m.positions.size()));
                m.positions.push_back(mPositions[mFaces[3 * f + k]]);
                m.facePlanes.push_back(plane);
            }
        }
    for (const Edge& e : mEdges) {
        if (e.face0 == kNoFace || e.face1 == kNoFace) continue;
        const glm::vec3 &p = mPositions[e.v0], &q = mPositions[e.v1];
        pushEdgeQuad(m, p, q, facePlane(e.face0), facePlane(e.face1));
        // The twins: face1's twin traverses v0 -> v1, face0's v1 -> v0.
        if (twoSheets) pushEdgeQuad(m, p, q, -facePlane(e.face1), -facePlane(e.face0));
    }
    if (twoSheets)
        for (size_t f = 0; f < faceCount(); ++f)
            for (size_t k = 0; k < 3; ++k) {
                if (pairedInMesh(f, k)) continue;
                const glm::vec3& p = mPositions[mFaces[3 * f + k]];
                const glm::vec3& q = mPositions[mFaces[3 * f + (k + 1) % 3]];
                pushEdgeQuad(m, p, q, facePlane(f), -facePlane(f));
            }
    return m;
}

} // namespace sb
