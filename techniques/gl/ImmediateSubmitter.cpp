#include "techniques/gl/ImmediateSubmitter.h"

#include <epoxy/gl.h>

namespace sb {

void ImmediateSubmitter::uploadMode(const Scene& scene) {
    mScene = &scene;
}

void ImmediateSubmitter::drawKept(DrawSet set, InstanceMask keep) {
    glBindVertexArray(0);
    mStats.glCalls += 1;
    for (size_t i = 0; i < mScene->instances.size(); ++i) {
        const Instance& inst = mScene->instances[i];
        if (!inDrawSet(inst, set) || !keptBy(keep, i)) continue;
        const Mesh& mesh = mScene->meshes[inst.mesh];
        cullFor(i);
        setInstanceUniforms(inst);
        emitImmediate(mesh);
        mStats.drawCalls += 1;
        mStats.triangles += mesh.triangleCount();
        mStats.instances += 1;
        mStats.glCalls += kInstanceUniformCalls + immediateCalls(mesh);
    }
    flushBufferedVertices();
    mStats.glCalls += 1;
}

void ImmediateSubmitter::flushBufferedVertices() {
    // An empty draw: every implementation must order a draw after the vertices before it, and Mesa
    // does so by flushing its glBegin/glEnd buffer (FLUSH_FOR_DRAW) before it sees the count of 0.
    // Unlike glFlush it does not hand the frame to the rasteriser early.
    glDrawArrays(GL_TRIANGLES, 0, 0);
}

} // namespace sb
