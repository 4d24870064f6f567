#include "techniques/gl/DisplayListSubmitter.h"

namespace sb {

DisplayListSubmitter::~DisplayListSubmitter() {
    release();
}

void DisplayListSubmitter::release() {
    if (mListCount) glDeleteLists(mFirstList, mListCount);
    mFirstList = 0;
    mListCount = 0;
}

void DisplayListSubmitter::uploadMode(const Scene& scene) {
    release();
    mScene = &scene;
    mListCount = GLsizei(scene.meshes.size());
    if (!mListCount) return;
    glBindVertexArray(0);
    mFirstList = glGenLists(mListCount);
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        const Mesh& mesh = scene.meshes[m];
        glNewList(mFirstList + GLuint(m), GL_COMPILE);
        emitImmediate(mesh);
        glEndList();
    }
}

void DisplayListSubmitter::drawKept(DrawSet set, InstanceMask keep) {
    glBindVertexArray(0);
    mStats.glCalls += 1;
    for (size_t i = 0; i < mScene->instances.size(); ++i) {
        const Instance& inst = mScene->instances[i];
        if (!inDrawSet(inst, set) || !keptBy(keep, i)) continue;
        cullFor(i);
        setInstanceUniforms(inst);
        glCallList(mFirstList + inst.mesh);
        mStats.drawCalls += 1;
        mStats.triangles += mScene->meshes[inst.mesh].triangleCount();
        mStats.instances += 1;
        mStats.glCalls += kInstanceUniformCalls + 1;
    }
}

} // namespace sb
