#pragma once
#include "techniques/SubmissionPlan.h"
#include "techniques/gl/MeshBuffers.h"
#include "techniques/gl/Submitter.h"

namespace sb {

/// One glDrawElementsInstanced per (mesh, draw set) and run of kept instances. The batches, their
/// instance records (attributes 4..8, divisor 1) and the runs come from the scene's SubmissionPlan
/// (techniques/SubmissionPlan.h): each draw set has its own contiguous range so a caster-only pass is
/// still one draw per mesh.
class InstancedSubmitter final : public Submitter {
public:
    ~InstancedSubmitter() override;
    SubmitMode mode() const override { return SubmitMode::Instanced; }
    void uploadMode(const Scene& scene) override;
    void instancesMovedMode(const Scene& scene) override;
    Defines defines() const override { return {{"SB_INSTANCED", ""}}; }

    /// Binds `buffer` (InstanceRecords, techniques/SubmissionPlan.h) to `vao` at binding 1 with divisor
    /// 1: attributes 4..7 (model) and 8 (colour + id). Also for techniques drawing their own instanced
    /// geometry.
    static void attachInstances(GLuint vao, GLuint buffer);

private:
    void drawKept(DrawSet set, InstanceMask keep) override;
    void release();
    void drawRun(const SubmissionPlan::Batch& b, uint32_t first, uint32_t count);
    MeshBuffers mBuffers;
    GLuint mInstanceBuffer = 0;
    SubmissionPlan mPlan; ///< the instance buffer's contents (rewritten when instances move) and batches
};

} // namespace sb
