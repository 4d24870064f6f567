#pragma once
// Receiver sections of the occluder technique (Coleman, "Fast Self-Shadowing Using Occluder Textures",
// section 5): the thesis cut the teapot into three objects (top, front, back), each drawn with only the
// shadow planes of its own section, because the spout's planes would otherwise shadow the spout itself
// and the lid's the far side of the body. Here a plane names the mesh parts that receive it
// (ShadowPlane::receivers) and one mesh is drawn as before; the vertex stage finds which planes its
// vertex receives in a per-mesh hash table keyed by the vertex position's bits.
//
// Why a table keyed by position and not a vertex attribute or gl_VertexID: the submitters feed only
// position and normal, and immediate mode and display lists number their vertices in Mesa's own way
// (reference/GBufferRenderer.h), while the position reaches the vertex stage bit for bit in every mode.
//
// The table: open addressing with linear probing over a power of two of slots, at most half full; a slot
// is (x bits, y bits, z bits, mask), mask bit j = the mesh's plane j shadows this vertex, kEmpty for a
// free slot. A position used by several parts (a seam) gets the AND of their masks, so a section never
// receives a plane it was not given. shaders/occluder/scene.vert mirrors hash() and lookup().
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/Mesh.h"

namespace sb {

struct ReceiverSections {
    static constexpr uint32_t kEmpty = 0xFFFFFFFFu; ///< mask value of a free slot
    static constexpr uint32_t kAll = 0xFFFFu;       ///< every plane (16 at most)

    /// True when one of `planes` names receivers (else no table is needed).
    static bool needed(const std::vector<ShadowPlane>& planes);
    /// The table of `mesh` for the planes it is drawn with (at most 16). Throws sb::Error naming the mesh
    /// and plane for a receiver part the mesh does not have.
    static std::vector<glm::uvec4> build(const Mesh& mesh, const std::vector<ShadowPlane>& planes);
    /// The mask of planes the vertex at `p` receives: kAll when it is not in the table.
    static uint32_t lookup(const std::vector<glm::uvec4>& table, const glm::vec3& p);
    /// The slot hash of a position's bits (murmur3's finaliser over the three words).
    static uint32_t hash(const glm::uvec3& bits);
};

} // namespace sb
