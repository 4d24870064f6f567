#include "scenes/ClosedMesh.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <unordered_map>
#include <utility>
#include <vector>

namespace sb {

namespace {

/// The welded index of every vertex: vertices whose positions have the same bits share the lowest
/// index among them, -0 taken as +0 (a generator's pole at sin = 0 times cos < 0). Any matrix maps
/// -0 and +0 to equal values, so the welded vertices still land on the same pixels; any other
/// difference, however small, keeps them apart (a crack the rasteriser could show).
std::vector<uint32_t> weldByPosition(const Mesh& mesh) {
    struct Key {
        uint32_t x, y, z;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        size_t operator()(const Key& k) const {
            return (size_t(k.x) * 73856093u) ^ (size_t(k.y) * 19349663u) ^ (size_t(k.z) * 83492791u);
        }
    };
    std::unordered_map<Key, uint32_t, KeyHash> first;
    first.reserve(mesh.positions.size());
    std::vector<uint32_t> weld(mesh.positions.size());
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::vec3 p = mesh.positions[i] + glm::vec3(0.0f); // -0 + +0 = +0, the rest unchanged
        Key k;
        std::memcpy(&k.x, &p.x, 4);
        std::memcpy(&k.y, &p.y, 4);
        std::memcpy(&k.z, &p.z, 4);
        weld[i] = first.emplace(k, uint32_t(i)).first->second;
    }
    return weld;
}

uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
}

/// The net count of each undirected edge: +1 per directed (a, b) with a < b, -1 per (b, a). Every
/// count is 0 exactly when each directed edge is matched by as many opposite ones.
size_t countUnmatchedEdges(const std::vector<std::array<uint32_t, 3>>& triangles) {
    std::unordered_map<uint64_t, int64_t> net;
    net.reserve(triangles.size() * 3);
    for (const auto& t : triangles)
        for (int e = 0; e < 3; ++e) {
            const uint32_t a = t[size_t(e)], b = t[size_t((e + 1) % 3)];
            const uint64_t key = a < b ? (uint64_t(a) << 32 | b) : (uint64_t(b) << 32 | a);
            net[key] += a < b ? 1 : -1;
        }
    size_t unmatched = 0;
    for (const auto& [key, n] : net) unmatched += size_t(n < 0 ? -n : n);
    return unmatched;
}

} // namespace

ClosedMeshReport computeClosedness(const Mesh& mesh) {
    ClosedMeshReport report;
    const std::vector<uint32_t> weld = weldByPosition(mesh);
    std::vector<std::array<uint32_t, 3>> triangles;
    triangles.reserve(mesh.triangleCount());
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const uint32_t a = weld[mesh.indices[t]], b = weld[mesh.indices[t + 1]],
                       c = weld[mesh.indices[t + 2]];
        if (a == b || b == c || a == c) continue; // degenerate: no area, no edges of a surface
        triangles.push_back({a, b, c});
    }
    report.unmatchedEdges = countUnmatchedEdges(triangles);

    // Components by shared welded vertices, then each one's signed volume (the divergence theorem:
    // the sum of det(a, b, c) / 6 over its triangles, positive for outward counter-clockwise winding).
    // Positions are taken relative to the mesh's bounds centre and summed in double, so a closed mesh
    // far from the origin is not lost to rounding.
    std::vector<uint32_t> parent(mesh.positions.size());
    std::iota(parent.begin(), parent.end(), 0u);
    for (const auto& t : triangles) {
        parent[findRoot(parent, t[1])] = findRoot(parent, t[0]);
        parent[findRoot(parent, t[2])] = findRoot(parent, t[0]);
    }
    const glm::dvec3 centre(mesh.computeBounds().center());
    std::unordered_map<uint32_t, double> volume;
    for (const auto& t : triangles) {
        const glm::dvec3 a = glm::dvec3(mesh.positions[t[0]]) - centre;
        const glm::dvec3 b = glm::dvec3(mesh.positions[t[1]]) - centre;
        const glm::dvec3 c = glm::dvec3(mesh.positions[t[2]]) - centre;
        volume[findRoot(parent, t[0])] += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    report.components = volume.size();
    for (const auto& [root, v] : volume) report.inwardComponents += v > 0.0 ? 0 : 1;
    return report;
}

bool isClosedMesh(const Mesh& mesh) {
    return computeClosedness(mesh).closed();
}

} // namespace sb
