#include "techniques/gl/RetainedSubmitter.h"

#include "techniques/SubmissionPlan.h"

namespace sb {

void RetainedSubmitter::uploadMode(const Scene& scene) {
    mScene = &scene;
    mBuffers.upload(scene);
    mOrder = instancesByMesh(scene);
}

void RetainedSubmitter::drawKept(DrawSet set, InstanceMask keep) {
    uint32_t boundMesh = UINT32_MAX;
    for (uint32_t i : mOrder) {
        const Instance& inst = mScene->instances[i];
        if (!inDrawSet(inst, set) || !keptBy(keep, i)) continue;
        if (inst.mesh != boundMesh) {
            glBindVertexArray(mBuffers.vao(inst.mesh));
            boundMesh = inst.mesh;
            mStats.glCalls += 1;
        }
        cullFor(i);
        setInstanceUniforms(inst);
        glDrawElements(GL_TRIANGLES, mBuffers.indexCount(inst.mesh), GL_UNSIGNED_INT, nullptr);
        mStats.drawCalls += 1;
        mStats.triangles += uint64_t(mBuffers.indexCount(inst.mesh)) / 3;
        mStats.instances += 1;
        mStats.glCalls += kInstanceUniformCalls + 1;
    }
    glBindVertexArray(0);
    mStats.glCalls += 1;
}

} // namespace sb
