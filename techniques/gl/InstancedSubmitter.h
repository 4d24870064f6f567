#pragma once
#include <array>
#include <glm/glm.hpp>
#include <vector>

#include "techniques/gl/MeshBuffers.h"
#include "techniques/gl/Submitter.h"

namespace sb {

/// One glDrawElementsInstanced per (mesh, draw set). Per-instance model matrix and colour/id come from
/// an instance buffer (attributes 4..8, divisor 1); each draw set has its own contiguous range so a
/// caster-only pass is still one draw per mesh.
class InstancedSubmitter final : public Submitter {
public:
    ~InstancedSubmitter() override;
    SubmitMode mode() const override { return SubmitMode::Instanced; }
    void upload(const Scene& scene) override;
    void instancesMoved(const Scene& scene) override;
    Defines defines() const override { return {{"SB_INSTANCED", ""}}; }

    /// One instance as shaders/common/instance.glsl reads it with SB_INSTANCED.
    struct InstanceRecord {
        glm::mat4 model;
        glm::vec4 colorId; ///< rgb colour, w object id
    };
    /// Binds `buffer` (InstanceRecords) to `vao` at binding 1 with divisor 1: attributes 4..7 (model)
    /// and 8 (colour + id). Also for techniques drawing their own instanced geometry.
    static void attachInstances(GLuint vao, GLuint buffer);

private:
    void drawKept(DrawSet set, InstanceMask keep) override;
    struct Batch {
        uint32_t mesh = 0;
        uint32_t first = 0; ///< base instance in the instance buffer
        uint32_t count = 0;
    };
    void release();
    void drawRun(const Batch& b, uint32_t first, uint32_t count);
    const Scene* mScene = nullptr;
    MeshBuffers mBuffers;
    GLuint mInstanceBuffer = 0;
    std::array<std::vector<Batch>, kDrawSetCount> mBatches; ///< per DrawSet
    std::vector<uint32_t> mRecordInstance; ///< per instance-buffer record: its index in Scene::instances
    std::vector<InstanceRecord> mRecords;  ///< the buffer's contents (rewritten when instances move)
};

} // namespace sb
