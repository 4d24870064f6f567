#include "techniques/gl/RetainedSubmitter.h"

#include <algorithm>
#include <numeric>

namespace sb {

void RetainedSubmitter::upload(const Scene& scene) {
    mScene = &scene;
    mBuffers.upload(scene);
    mOrder.resize(scene.instances.size());
    std::iota(mOrder.begin(), mOrder.end(), 0u);
    std::stable_sort(mOrder.begin(), mOrder.end(), [&](uint32_t a, uint32_t b) {
        return scene.instances[a].mesh < scene.instances[b].mesh;
    });
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
