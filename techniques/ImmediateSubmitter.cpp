#include "techniques/ImmediateSubmitter.h"

#include <epoxy/gl.h>

namespace sb {

void ImmediateSubmitter::upload(const Scene& scene) {
    mScene = &scene;
}

void ImmediateSubmitter::draw(DrawSet set) {
    glBindVertexArray(0);
    for (const Instance& inst : mScene->instances) {
        if (!inSet(inst, set)) continue;
        const Mesh& mesh = mScene->meshes[inst.mesh];
        setInstanceUniforms(inst);
        glBegin(GL_TRIANGLES);
        for (uint32_t idx : mesh.indices) {
            glVertexAttrib3fv(1, &mesh.normals[idx].x);
            glVertexAttrib3fv(0, &mesh.positions[idx].x);
        }
        glEnd();
        mStats.drawCalls += 1;
        mStats.triangles += mesh.triangleCount();
        mStats.instances += 1;
    }
}

} // namespace sb
