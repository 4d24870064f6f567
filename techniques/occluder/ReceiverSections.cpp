#include "techniques/occluder/ReceiverSections.h"

#include <algorithm>
#include <bit>
#include <cstring>

#include "core/Error.h"

namespace sb {
namespace {

glm::uvec3 bitsOf(const glm::vec3& p) {
    glm::uvec3 b;
    std::memcpy(&b, &p, sizeof(b));
    return b;
}

/// Per part of the mesh, the mask of the first `count` planes it receives.
std::vector<uint32_t> partMasks(const Mesh& mesh, const std::vector<ShadowPlane>& planes) {
    std::vector<uint32_t> masks(mesh.parts.size(), 0);
    for (size_t j = 0; j < planes.size(); ++j) {
        const ShadowPlane& plane = planes[j];
        for (const std::string& name : plane.receivers)
            if (std::none_of(mesh.parts.begin(), mesh.parts.end(),
                             [&](const MeshPart& part) { return part.name == name; }))
                throw Error("occluder: mesh '" + mesh.name + "': shadow plane '" + plane.name +
                            "' names receiver part '" + name + "', which the mesh does not have");
        for (size_t k = 0; k < mesh.parts.size(); ++k) {
            const bool receives =
                plane.receivers.empty() || std::find(plane.receivers.begin(), plane.receivers.end(),
                                                     mesh.parts[k].name) != plane.receivers.end();
            if (receives) masks[k] |= 1u << j;
        }
    }
    return masks;
}

} // namespace

bool ReceiverSections::needed(const std::vector<ShadowPlane>& planes) {
    return std::any_of(planes.begin(), planes.end(),
                       [](const ShadowPlane& p) { return !p.receivers.empty(); });
}

uint32_t ReceiverSections::hash(const glm::uvec3& bits) {
    uint32_t h = bits.x;
    h = h * 0x9E3779B1u ^ bits.y;
    h = h * 0x85EBCA77u ^ bits.z;
    h ^= h >> 16;
    h *= 0x7FEB352Du;
    h ^= h >> 15;
    h *= 0x846CA68Bu;
    h ^= h >> 16;
    return h;
}

std::vector<glm::uvec4> ReceiverSections::build(const Mesh& mesh, const std::vector<ShadowPlane>& planes) {
    const size_t count = planes.size();
    const std::vector<uint32_t> masks = partMasks(mesh, planes);
    // Per vertex the AND over the parts whose triangles use it; vertices no part uses keep every plane.
    const uint32_t used = (1u << count) - 1u; // count <= 16
    std::vector<uint32_t> vertexMask(mesh.positions.size(), used);
    for (size_t k = 0; k < mesh.parts.size(); ++k) {
        const MeshPart& part = mesh.parts[k];
        for (uint32_t i = part.firstIndex; i < part.firstIndex + part.indexCount; ++i)
            vertexMask[mesh.indices[i]] &= masks[k];
    }
    const size_t slots = std::bit_ceil(std::max<size_t>(2, 2 * mesh.positions.size()));
    std::vector<glm::uvec4> table(slots, glm::uvec4(0, 0, 0, kEmpty));
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        const glm::uvec3 key = bitsOf(mesh.positions[v]);
        // Vertices at the same position (seams, duplicated for normals) share a slot: AND of masks.
        for (size_t s = hash(key) & (slots - 1);; s = (s + 1) & (slots - 1)) {
            glm::uvec4& slot = table[s];
            if (slot.w == kEmpty) {
                slot = glm::uvec4(key, vertexMask[v]);
                break;
            }
            if (glm::uvec3(slot) == key) {
                slot.w &= vertexMask[v];
                break;
            }
        }
    }
    return table;
}

uint32_t ReceiverSections::lookup(const std::vector<glm::uvec4>& table, const glm::vec3& p) {
    if (table.empty()) return kAll;
    const glm::uvec3 key = bitsOf(p);
    const size_t slots = table.size();
    for (size_t s = hash(key) & (slots - 1), n = 0; n < slots; s = (s + 1) & (slots - 1), ++n) {
        if (table[s].w == kEmpty) return kAll;
        if (glm::uvec3(table[s]) == key) return table[s].w;
    }
    return kAll;
}

} // namespace sb
