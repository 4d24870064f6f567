#pragma once
// The CPU side of submission (docs/ARCHITECTURE.md, "Submission"), written once for both APIs: what the
// GL submitters (techniques/gl/MeshBuffers.h, techniques/gl/InstancedSubmitter.h,
// techniques/gl/RetainedSubmitter.h) and the Vulkan submitter (techniques/vulkan/VulkanSubmitter.h) upload
// and in which order they draw it. Each API only turns this plan into its buffers and calls, so the two
// send the same vertices, the same instance records and the same runs of instances.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/DrawSet.h"
#include "scenes/Scene.h"

namespace sb {

/// A mesh's vertex stream: per vertex its position (attribute 0) then its normal (attribute 1), three
/// floats each, interleaved in one buffer of stride kVertexStride.
constexpr size_t kVertexStride = 2 * sizeof(glm::vec3);
constexpr size_t kNormalOffset = sizeof(glm::vec3); ///< attribute 1's offset within a vertex

/// `mesh`'s vertices interleaved (position, normal): the contents of its vertex buffer on either API.
std::vector<glm::vec3> interleavedVertices(const Mesh& mesh);

/// Indices into Scene::instances sorted by mesh, scene order kept within a mesh: the draw order of the
/// retained modes (GL and Vulkan), so a draw binds each mesh once, not once per instance.
std::vector<uint32_t> instancesByMesh(const Scene& scene);

/// One instance as shaders/common/instance.glsl reads it with SB_INSTANCED, from a buffer bound with
/// divisor 1 (GL) or VK_VERTEX_INPUT_RATE_INSTANCE (Vulkan) at stride sizeof(InstanceRecord):
///   attributes 4..7  `aModel`, the model matrix, one column (vec4) each at offsets 0, 16, 32, 48;
///   attribute  8     `aColorId` at offset 64: rgb the instance colour, w its shadow-signed object id
///                    (scenes/DrawSet.h's shadowSignedId).
/// Also the record a technique's own instanced geometry uses (techniques/planar/PlanarGL.cpp's proxies).
struct InstanceRecord {
    glm::mat4 model;
    glm::vec4 colorId;
};
static_assert(sizeof(InstanceRecord) == 80 && offsetof(InstanceRecord, colorId) == 64,
              "InstanceRecord must stay what attributes 4..8 of shaders/common/instance.glsl read");

/// The instanced plan of a scene: one array of InstanceRecords holding, per DrawSet and mesh, that set's
/// instances of the mesh contiguously in scene order (an instance appears once per set it belongs to), so
/// a draw of any set is one batch per mesh, and culling splits a batch into runs of consecutive kept
/// records instead of uploading new ones.
class SubmissionPlan {
public:
    /// A DrawSet's instances of one mesh: records [first, first + count).
    struct Batch {
        uint32_t mesh = 0;
        uint32_t first = 0; ///< the first record (the base instance of the draw)
        uint32_t count = 0;
    };

    SubmissionPlan() = default; ///< empty: no records, no batches
    /// Batches for every DrawSet in the order of the DrawSet enum: sets outermost, then meshes in scene
    /// order, then instances in scene order. Meshes a set has no instance of get no batch.
    explicit SubmissionPlan(const Scene& scene);

    /// The records in upload order: the instance buffer's contents.
    const std::vector<InstanceRecord>& records() const { return mRecords; }
    /// The batches of `set`, meshes in scene order, empty ones left out.
    std::span<const Batch> batches(DrawSet set) const { return mBatches[size_t(set)]; }
    /// The instance (index into Scene::instances) that record `record` holds.
    uint32_t instanceOf(uint32_t record) const { return mRecordInstance[record]; }

    /// A scene in motion moved its instances: rewrites every record's model matrix from `scene` (the
    /// scene the plan was built from), in place. The caller uploads records() again, whole: what an
    /// application streaming its instance transforms does.
    void instancesMoved(const Scene& scene);

    /// Calls `run(first, count)` for each run of consecutive records of `batch` whose instances `keep`
    /// keeps (empty: the whole batch as one run), in record order; `first` is a record index (the base
    /// instance of the run's draw). A batch with no kept record makes no call.
    template <class RunFn>
    void forEachKeptRun(const Batch& batch, InstanceMask keep, RunFn&& run) const;
    /// As above, and a run also ends where `split` (indexed like Scene::instances; empty: all 0)
    /// changes: run(first, count, value) gets the run's split value (a pass's back-face decisions).
    template <class RunFn>
    void forEachKeptRun(const Batch& batch, InstanceMask keep, InstanceMask split, RunFn&& run) const;

private:
    std::vector<InstanceRecord> mRecords;
    std::vector<uint32_t> mRecordInstance; ///< per record: its index in Scene::instances
    std::array<std::vector<Batch>, kDrawSetCount> mBatches;
};

template <class RunFn>
void SubmissionPlan::forEachKeptRun(const Batch& batch, InstanceMask keep, RunFn&& run) const {
    forEachKeptRun(batch, keep, InstanceMask{},
                   [&](uint32_t first, uint32_t count, bool) { run(first, count); });
}

template <class RunFn>
void SubmissionPlan::forEachKeptRun(const Batch& batch, InstanceMask keep, InstanceMask split,
                                    RunFn&& run) const {
    // Inline: it runs per batch and pass inside the timed frame.
    auto value = [&](uint32_t r) { return !split.empty() && split[mRecordInstance[r]] != 0; };
    for (uint32_t r = batch.first, end = batch.first + batch.count; r < end;) {
        if (!keptBy(keep, mRecordInstance[r])) {
            ++r;
            continue;
        }
        const bool v = value(r);
        uint32_t runEnd = r + 1;
        while (runEnd < end && keptBy(keep, mRecordInstance[runEnd]) && value(runEnd) == v) ++runEnd;
        run(r, runEnd - r, v);
        r = runEnd;
    }
}

} // namespace sb
