#pragma once
// What the GPU silhouette paths of `volume` read (extrusion=geometry, compute; techniques/volume/
// VolumePlanner.h), built once per mesh from its welded form, free of any API so GL and Vulkan upload
// the same bytes and tests read them:
//  - triangles with adjacency for shaders/volume/silhouette.geom: per face 6 vertices of 3 vec4
//    (position w = 1, the normal of the face the vertex stands for, that face's first vertex); slot
//    2k is the face's vertex k with the face's own data, slot 2k + 1 the vertex opposite edge
//    (k, k + 1) in the face across it, with that face's data;
//  - face records for shaders/volume/silhouette.comp (std430: uvec4 vertices, uvec4 neighbours, vec4
//    normal, vec4 first vertex).
// Where an edge has no face across (open meshes, which the GPU paths refuse) the face stands across
// from itself and so never builds a side there.
#include <vector>

#include <glm/glm.hpp>

#include "techniques/volume/ShadowVolumeMesh.h"

namespace sb {

struct SilhouetteFace {
    glm::uvec4 vertices{0u};   ///< welded indices, counter-clockwise, w unused
    glm::uvec4 neighbours{0u}; ///< the face across (v0, v1), (v1, v2), (v2, v0), w unused
    glm::vec4 normal{0.0f};    ///< ShadowVolumeMesh::faceNormals, w = 0
    glm::vec4 first{0.0f};     ///< the face's first vertex, w = 1
};
static_assert(sizeof(SilhouetteFace) == 64, "std430 layout of shaders/volume/silhouette.comp's Face");

struct SilhouetteInputs {
    /// 18 vec4 per face (6 vertices of 3 vec4), GL_TRIANGLES_ADJACENCY's order.
    static std::vector<glm::vec4> adjacencyVertices(const ShadowVolumeMesh& mesh);
    static constexpr int kVec4PerVertex = 3, kVerticesPerFace = 6;
    /// One record per face.
    static std::vector<SilhouetteFace> faces(const ShadowVolumeMesh& mesh);
    /// The most vertices the compute path writes for one face: its cap and a side (6) on each edge.
    static constexpr size_t kMaxVerticesPerFace = 3 + 3 * 6;
};

} // namespace sb
