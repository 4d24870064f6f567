#include "techniques/occluder/OccluderMeshCache.h"

#include <cstring>
#include <list>
#include <mutex>
#include <optional>
#include <string_view>

namespace sb {

namespace {

template <typename T>
std::string_view bytesOf(const std::vector<T>& v) {
    return {reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T)};
}

/// Bit for bit: -0 and 0, or two NaNs, are different inputs to the arithmetic downstream.
template <typename T>
bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
    return bytesOf(a) == bytesOf(b);
}

void hashCombine(size_t& seed, size_t value) {
    seed ^= value + 0x9e3779b97f4a7c15ull + (seed << 6) + (seed >> 2);
}

/// A copy of what the chooser and the bake read of a mesh.
struct MeshRecord {
    size_t hash = 0;
    std::string name;
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> indices;
    std::vector<MeshPart> parts;

    static size_t hashOf(const Mesh& mesh) {
        const std::hash<std::string_view> h;
        size_t seed = h(bytesOf(mesh.positions));
        hashCombine(seed, h(bytesOf(mesh.indices)));
        hashCombine(seed, h(mesh.name));
        for (const MeshPart& p : mesh.parts) {
            hashCombine(seed, h(p.name));
            hashCombine(seed, (size_t(p.firstIndex) << 32) | p.indexCount);
        }
        return seed;
    }
    bool sameAs(const Mesh& mesh, size_t meshHash) const {
        if (hash != meshHash || name != mesh.name || parts.size() != mesh.parts.size() ||
            !sameBytes(indices, mesh.indices) || !sameBytes(positions, mesh.positions))
            return false;
        for (size_t i = 0; i < parts.size(); ++i)
            if (parts[i].name != mesh.parts[i].name || parts[i].firstIndex != mesh.parts[i].firstIndex ||
                parts[i].indexCount != mesh.parts[i].indexCount)
                return false;
        return true;
    }
    size_t bytes() const {
        return positions.size() * sizeof(glm::vec3) + indices.size() * sizeof(uint32_t) + sizeof(*this);
    }
};

struct Entry {
    std::shared_ptr<const MeshRecord> mesh;
    std::string key; ///< "choice:" or "texels:" and the other inputs
    std::optional<ShadowPlaneChoice> choice;
    OccluderMeshCache::Texels texels;
    size_t bytes = 0;
};

constexpr size_t kDefaultMaxBytes = size_t(256) << 20;

struct Store {
    std::mutex mutex;
    std::list<Entry> entries; ///< most recently used first
    OccluderMeshCache::Stats stats;
    size_t maxBytes = kDefaultMaxBytes;

    /// The entry for (mesh, key), moved to the front; nullptr when absent. Locked by the caller.
    const Entry* find(const Mesh& mesh, size_t meshHash, const std::string& key) {
        for (auto it = entries.begin(); it != entries.end(); ++it)
            if (it->key == key && it->mesh->sameAs(mesh, meshHash)) {
                entries.splice(entries.begin(), entries, it);
                return &entries.front();
            }
        return nullptr;
    }
    /// The stored copy of `mesh` when an entry holds one, else a new copy. Locked by the caller.
    std::shared_ptr<const MeshRecord> record(const Mesh& mesh, size_t meshHash) {
        for (const Entry& e : entries)
            if (e.mesh->sameAs(mesh, meshHash)) return e.mesh;
        return std::make_shared<const MeshRecord>(
            MeshRecord{meshHash, mesh.name, mesh.positions, mesh.indices, mesh.parts});
    }
    /// Adds `e` at the front and evicts from the back down to maxBytes. Locked by the caller.
    void add(Entry e) {
        e.bytes += e.mesh->bytes() + e.key.size() + sizeof(Entry);
        stats.bytes += e.bytes;
        entries.push_front(std::move(e));
        shrink();
    }
    void shrink() {
        while (!entries.empty() && stats.bytes > maxBytes) {
            stats.bytes -= entries.back().bytes;
            entries.pop_back();
        }
        stats.entries = entries.size();
    }
};

Store& store() {
    static Store s;
    return s;
}

std::string choiceKey(const std::vector<glm::vec3>& towardLight, int maxPlanes) {
    return "choice:" + std::to_string(maxPlanes) + ":" + std::string(bytesOf(towardLight));
}

} // namespace

ShadowPlaneChoice OccluderMeshCache::choose(const Mesh& mesh, const std::vector<glm::vec3>& towardLight,
                                            int maxPlanes) {
    const size_t meshHash = MeshRecord::hashOf(mesh);
    const std::string key = choiceKey(towardLight, maxPlanes);
    Store& s = store();
    {
        std::lock_guard lock(s.mutex);
        if (const Entry* e = s.find(mesh, meshHash, key)) {
            ++s.stats.choiceHits;
            return *e->choice;
        }
    }
    // Computed outside the lock: a second thread asking for the same input computes it too, which
    // costs only time.
    ShadowPlaneChoice choice = ShadowPlaneChooser::choose(mesh, towardLight, maxPlanes);
    std::lock_guard lock(s.mutex);
    ++s.stats.choiceMisses;
    Entry e{s.record(mesh, meshHash), key, choice, nullptr, 0};
    for (const ShadowPlane& p : choice.planes) e.bytes += sizeof(p) + p.name.size();
    s.add(std::move(e));
    return choice;
}

OccluderMeshCache::Texels OccluderMeshCache::texels(const Mesh& mesh, const std::string& key,
                                                    const std::function<std::vector<uint8_t>()>& bake) {
    const size_t meshHash = MeshRecord::hashOf(mesh);
    const std::string fullKey = "texels:" + key;
    Store& s = store();
    {
        std::lock_guard lock(s.mutex);
        if (const Entry* e = s.find(mesh, meshHash, fullKey)) {
            ++s.stats.texelHits;
            return e->texels;
        }
    }
    Texels made = std::make_shared<const std::vector<uint8_t>>(bake());
    std::lock_guard lock(s.mutex);
    ++s.stats.texelMisses;
    s.add({s.record(mesh, meshHash), fullKey, std::nullopt, made, made->size()});
    return made;
}

OccluderMeshCache::Stats OccluderMeshCache::stats() {
    std::lock_guard lock(store().mutex);
    return store().stats;
}

void OccluderMeshCache::clear() {
    Store& s = store();
    std::lock_guard lock(s.mutex);
    s.entries.clear();
    s.stats = {};
}

void OccluderMeshCache::setMaxBytes(size_t bytes) {
    Store& s = store();
    std::lock_guard lock(s.mutex);
    s.maxBytes = bytes;
    s.shrink();
}

size_t OccluderMeshCache::maxBytes() {
    std::lock_guard lock(store().mutex);
    return store().maxBytes;
}

} // namespace sb
