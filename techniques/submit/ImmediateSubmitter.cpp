#include "techniques/submit/ImmediateSubmitter.h"

#include <epoxy/gl.h>

namespace sb {

void ImmediateSubmitter::upload(const Scene& scene) {
    mScene = &scene;
}

void ImmediateSubmitter::draw(DrawSet set) {
    glBindVertexArray(0);
    mStats.glCalls += 1;
    for (const Instance& inst : mScene->instances) {
        if (!inSet(inst, set)) continue;
        const Mesh& mesh = mScene->meshes[inst.mesh];
        setInstanceUniforms(inst);
        emitImmediate(mesh);
        mStats.drawCalls += 1;
        mStats.triangles += mesh.triangleCount();
        mStats.instances += 1;
        mStats.glCalls += kInstanceUniformCalls + immediateCalls(mesh);
    }
}

} // namespace sb
