#pragma once
// Indexed triangle mesh in object space: the one geometry format every technique and submitter reads.
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/ShadowPlane.h"
#include "scenes/ShadowProxy.h"

namespace sb {

struct Aabb {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{-std::numeric_limits<float>::max()};
    void extend(const glm::vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void extend(const Aabb& b) {
        if (!b.empty()) {
            extend(b.min);
            extend(b.max);
        }
    }
    bool empty() const { return min.x > max.x; }
    glm::vec3 center() const { return 0.5f * (min + max); }
    glm::vec3 extent() const { return max - min; }
    /// The 8 corners; bit 0 of the index picks max.x, bit 1 max.y, bit 2 max.z.
    std::array<glm::vec3, 8> corners() const {
        std::array<glm::vec3, 8> c;
        for (int i = 0; i < 8; ++i)
            c[size_t(i)] = {(i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z};
        return c;
    }
};

/// A named part of a mesh (a contiguous index range), e.g. the teapot's lid, spout, handle, body or
/// the aircraft's tail fins. Later techniques (occluder planes, proxies) refer to parts by name.
struct MeshPart {
    std::string name;
    uint32_t firstIndex = 0; ///< into Mesh::indices
    uint32_t indexCount = 0;
};

struct Mesh {
    std::string name;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals; ///< per vertex, unit length, same count as positions
    std::vector<uint32_t> indices;  ///< triangle list, counter-clockwise front faces
    std::vector<MeshPart> parts;    ///< optional; empty means one part covering everything
    /// Occluder-texture shadow planes in object space (the `occluder` technique): declared per mesh in
    /// the scene file or built in for generated content (scenes/BuiltinShadowPlanes.h).
    std::vector<ShadowPlane> shadowPlanes;
    /// No planes were given or built in for this geometry (a --model file, a generator other than the
    /// aircraft and the teapot, a model file without "shadow_planes"): the occluder technique chooses
    /// them for the scene's lights (scenes/ShadowPlaneChooser.h).
    bool shadowPlanesAuto = false;
    /// ShadowProxies in object space (the `proxy` technique), declared per mesh in the scene file
    /// ("proxies"); when not declared (proxiesDeclared false) the technique fits the tightest sphere,
    /// box or cylinder to each instance (ShadowProxy::fit). Declared and empty: the mesh has none.
    std::vector<ShadowProxy> proxies;
    bool proxiesDeclared = false;
    /// Back faces of this mesh are never seen from outside it: an oriented, outward-wound surface
    /// without boundary (scenes/ClosedMesh.h), computed at load, or asserted by the scene file's
    /// "closed". Only then may a pass cull its back faces (scenes/BackFaceCulling.h). False (the
    /// default for meshes built in code): both faces are drawn.
    bool closed = false;
    bool closedDeclared = false; ///< `closed` came from the scene file (it then enters the content hash)

    size_t vertexCount() const { return positions.size(); }
    size_t triangleCount() const { return indices.size() / 3; }
    Aabb computeBounds() const {
        Aabb b;
        for (const auto& p : positions) b.extend(p);
        return b;
    }
};

} // namespace sb
