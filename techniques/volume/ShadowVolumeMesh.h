#pragma once
// The mesh preparation of stencil shadow volumes (GPU Gems ch. 9, section 9.2.2), untimed, once per
// mesh in VolumeGL::setScene:
//  - welding: coincident positions (within a tolerance relative to the mesh's bounds) become one
//    vertex, so the seams generators and model files leave for normals and texture coordinates do not
//    count as cracks;
//  - the doubled vertex buffer: n welded vertices as (x, y, z, 1) followed by the same n as
//    (x, y, z, 0), which the extrusion shader sends to infinity away from the light (Listing 9-3);
//  - faces (three welded indices, counter-clockwise) with unnormalised face normals; faces that
//    collapse to an edge or a point after welding are dropped (counted), zero-area faces with three
//    distinct vertices are kept (their normal is zero: they classify as light-facing, which keeps the
//    volume closed);
//  - edges with the two adjacent faces, oriented so that v0 -> v1 is counter-clockwise in face0 and
//    clockwise in face1 (the chapter's convention), and the count of open edges: edges that do not
//    have exactly one face in each direction (a crack: one face; non-manifold: more).
// Per frame, buildVolume() is the chapter's findBackfaces + renderShadowCaps + renderShadowSides on
// the CPU for one caster and one object-space light. buildExtrusionMesh() is the second path: the
// McGuire-Hughes (2003) mesh whose vertex shader extrudes silhouettes without the CPU.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/Mesh.h"

namespace sb {

/// How a volume treats edges that do not have exactly two oppositely wound faces.
enum class OpenEdgePolicy {
    /// The chapter's closed-mesh rule: faces facing the light form the light cap, the others (sent to
    /// infinity) the dark cap, and sides are extruded from edges between the two. Only valid for
    /// closed meshes: VolumeGL refuses a mesh with open edges under this policy.
    Closed,
    /// Robust for any mesh: every face is an occluder seen from either side, oriented towards the
    /// light; each edge gets a side quad per unit of multiplicity m = (faces traversing v0->v1) -
    /// (faces traversing v1->v0) after orientation, drawn |m| times wound by sign(m). A closed mesh
    /// gives count 2 inside its shadow instead of 1 (both walls occlude), open edges get their sides.
    Multiplicity,
};

/// One caster's shadow volume for one light, as indices into the doubled vertex buffer.
struct VolumeIndices {
    std::vector<uint32_t> lightCap; ///< triangles, w = 1 vertices
    std::vector<uint32_t> darkCap;  ///< triangles, w = 0 vertices (empty in the directional form)
    std::vector<uint32_t> sides;    ///< triangles: quads split in two, or (v0, v1, n) for directional
    uint32_t silhouetteEdges = 0;   ///< edges that produced a side (each counted once, whatever |m|)
};

/// What buildVolume() should produce.
struct VolumeRequest {
    /// Object-space light: (position, 1) for point and spot, (vector towards the light, 0) for
    /// directional (the chapter's L; Listing 9-5).
    glm::vec4 light{0.0f, 1.0f, 0.0f, 0.0f};
    bool caps = true;     ///< false: sides only (z-pass needs no caps)
    bool lightCap = true; ///< each cap can be culled on its own (section 9.5.3)
    bool darkCap = true;
    bool sides = true;
    /// Directional-light form (section 9.5.1): sides as triangles (v0, v1, n) converging on the one
    /// point at infinity, no dark cap. Only meaningful when light.w == 0.
    bool directionalForm = false;
    OpenEdgePolicy policy = OpenEdgePolicy::Closed;
};

/// The McGuire-Hughes extrusion mesh: every vertex carries the plane of the face it stands for
/// (attribute `facePlane`: unnormalised N and dot(N, P0)), and the vertex shader sends it to infinity
/// when dot(N, L.xyz) - L.w * plane.w < 0 (Listing 9-5 in plane form). Each face is emitted with its
/// three vertices (light cap when lit, dark cap when not) and each edge as a degenerate quad
/// [v1(face0), v0(face0), v0(face1), v1(face1)] that opens into a side exactly when the edge is a
/// silhouette. Under OpenEdgePolicy::Closed open edges get no quad; under Multiplicity an open mesh is
/// emitted as two sheets (see buildExtrusionMesh).
struct ExtrusionMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec4> facePlanes; ///< per vertex: (N, dot(N, P0)) of its face, N unnormalised
    std::vector<uint32_t> capIndices;  ///< 3 per face and sheet
    std::vector<uint32_t> sideIndices; ///< 6 per quad
    bool twoSheets = false;            ///< the open-mesh form: every face and its reversed twin
};

class ShadowVolumeMesh {
public:
    /// Welds and builds adjacency. `weldTolerance` is relative to the largest extent of the mesh's
    /// bounds (1e-6: float noise of generators, not modelling gaps).
    explicit ShadowVolumeMesh(const Mesh& mesh, float weldTolerance = 1e-6f);

    const std::string& name() const { return mName; }
    /// Welded vertex count n; the doubled buffer has 2n entries.
    uint32_t vertexCount() const { return uint32_t(mPositions.size()); }
    const std::vector<glm::vec3>& positions() const { return mPositions; }
    /// 2n entries: (p, 1) then (p, 0).
    std::vector<glm::vec4> doubledVertices() const;
    size_t faceCount() const { return mFaces.size() / 3; }
    const std::vector<uint32_t>& faces() const { return mFaces; } ///< 3 welded indices per face
    const std::vector<glm::vec3>& faceNormals() const { return mFaceNormals; }
    size_t edgeCount() const { return mEdges.size(); }
    /// Edges without exactly one face in each direction (0 for a closed, consistently wound mesh).
    size_t openEdgeCount() const { return mOpenEdges; }
    bool closed() const { return mOpenEdges == 0; }
    /// Faces dropped because welding collapsed them (two equal vertex indices).
    size_t collapsedFaceCount() const { return mCollapsedFaces; }
    /// Vertices merged by welding (input count minus welded count).
    size_t weldedAway() const { return mWeldedAway; }

    /// light.w == 0 ? dot(N, L.xyz) < 0 : dot(N, L.xyz - P0) < 0 per face (Listing 9-5), into `out`.
    void classifyFaces(const glm::vec4& light, std::vector<uint8_t>& out) const;
    /// The volume of this mesh for one light (Listings 9-6, 9-7 and section 9.5.1). Reuses `out`'s
    /// storage: no allocation per frame once the vectors have grown.
    void buildVolume(const VolumeRequest& request, VolumeIndices& out) const;
    /// The precomputed mesh for vertex-shader extrusion (McGuire and Hughes 2003). Multiplicity on a
    /// mesh with open edges adds the reversed twin of every face, so that the surface is closed and
    /// every crack gets its side (the vertex-shader counterpart of buildVolume's multiplicity).
    ExtrusionMesh buildExtrusionMesh(OpenEdgePolicy policy = OpenEdgePolicy::Closed) const;
    /// 3 per face, for its directed edges (f0 -> f1, f1 -> f2, f2 -> f0): the face across that edge
    /// (traversing it the other way), kNoFace where there is none. The GPU silhouette paths' adjacency:
    /// a face finds the silhouette edges it owns from its own and its neighbours' classification.
    std::vector<uint32_t> neighbours() const;
    /// (N, dot(N, P0)) of face f.
    glm::vec4 facePlane(size_t f) const;

    struct Edge {
        uint32_t v0 = 0, v1 = 0; ///< v0 < v1 for edges without a face0 (then face1 is the one face)
        /// face0: a face traversing v0 -> v1; face1: a face traversing v1 -> v0; kNoFace if none.
        /// Further faces of a non-manifold edge are only in faceEdges().
        uint32_t face0 = kNoFace, face1 = kNoFace;
    };
    static constexpr uint32_t kNoFace = 0xffffffffu;
    const std::vector<Edge>& edges() const { return mEdges; }
    /// 3 per face, for the face's directed edges (f0 -> f1, f1 -> f2, f2 -> f0): the edge index, with
    /// the top bit set when the face traverses that edge from v1 to v0. The multiplicity policy sums
    /// these signs over the light-facing-oriented faces.
    const std::vector<uint32_t>& faceEdges() const { return mFaceEdges; }
    static constexpr uint32_t kReversed = 0x80000000u;

private:
    /// Whether the k-th directed edge of `face` has a partner of the opposite direction in edges().
    bool pairedInMesh(size_t face, size_t k) const;

    std::string mName;
    std::vector<glm::vec3> mPositions;
    std::vector<uint32_t> mFaces;
    std::vector<glm::vec3> mFaceNormals;
    std::vector<Edge> mEdges;
    std::vector<uint32_t> mFaceEdges;
    mutable std::vector<int32_t> mMultiplicity; ///< scratch of the multiplicity policy
    size_t mOpenEdges = 0, mCollapsedFaces = 0, mWeldedAway = 0;
    mutable std::vector<uint8_t> mBackface; ///< scratch of buildVolume
};

} // namespace sb
