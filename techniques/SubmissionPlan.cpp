#include "techniques/SubmissionPlan.h"

#include <algorithm>
#include <numeric>

namespace sb {

std::vector<glm::vec3> interleavedVertices(const Mesh& mesh) {
    // Interleaved (position, normal): one stream, one cache line per vertex fetch.
    std::vector<glm::vec3> interleaved;
    interleaved.reserve(mesh.positions.size() * 2);
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        interleaved.push_back(mesh.positions[i]);
        interleaved.push_back(mesh.normals[i]);
    }
    return interleaved;
}

std::vector<uint32_t> instancesByMesh(const Scene& scene) {
    std::vector<uint32_t> order(scene.instances.size());
    std::iota(order.begin(), order.end(), 0u);
    // Stable: within a mesh the instances keep scene order, so the draw order is the scene's.
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        return scene.instances[a].mesh < scene.instances[b].mesh;
    });
    return order;
}

SubmissionPlan::SubmissionPlan(const Scene& scene) {
    // One pass over the instances per (set, mesh): upload-time work, and it keeps every batch contiguous.
    for (size_t s = 0; s < kDrawSetCount; ++s) {
        const DrawSet set = DrawSet(s);
        for (uint32_t m = 0; m < scene.meshes.size(); ++m) {
            Batch b{m, uint32_t(mRecords.size()), 0};
            for (uint32_t i = 0; i < scene.instances.size(); ++i) {
                const Instance& inst = scene.instances[i];
                if (inst.mesh != m || !inDrawSet(inst, set)) continue;
                mRecords.push_back({inst.model, glm::vec4(inst.color, shadowSignedId(inst))});
                mRecordInstance.push_back(i);
                ++b.count;
            }
            if (b.count) mBatches[s].push_back(b);
        }
    }
}

void SubmissionPlan::instancesMoved(const Scene& scene) {
    // Only the matrices move (scenes/Motion.h moves and turns casters; colours, ids and the shadow flags
    // stay as loaded), so the batches and the record->instance map stay valid.
    for (size_t r = 0; r < mRecords.size(); ++r)
        mRecords[r].model = scene.instances[mRecordInstance[r]].model;
}

} // namespace sb
