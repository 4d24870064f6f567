#include "techniques/gl/InstancedSubmitter.h"

#include <algorithm>

#include <glm/glm.hpp>

namespace sb {

InstancedSubmitter::~InstancedSubmitter() {
    release();
}

void InstancedSubmitter::release() {
    if (mInstanceBuffer) glDeleteBuffers(1, &mInstanceBuffer);
    mInstanceBuffer = 0;
}

void InstancedSubmitter::uploadMode(const Scene& scene) {
    release();
    mBuffers.upload(scene);
    // One buffer holding, per draw set and mesh, that set's instances contiguously.
    mPlan = SubmissionPlan(scene);
    const std::vector<InstanceRecord>& records = mPlan.records();
    glCreateBuffers(1, &mInstanceBuffer);
    // Dynamic storage: a scene in motion rewrites the records of its moving casters every frame.
    glNamedBufferStorage(mInstanceBuffer,
                         GLsizeiptr(std::max<size_t>(1, records.size()) * sizeof(InstanceRecord)),
                         records.empty() ? nullptr : records.data(), GL_DYNAMIC_STORAGE_BIT);
    // A VAO per mesh: the shared mesh buffers at binding 0, the instance buffer at binding 1.
    for (size_t m = 0; m < scene.meshes.size(); ++m) attachInstances(mBuffers.vao(m), mInstanceBuffer);
}

void InstancedSubmitter::instancesMovedMode(const Scene& scene) {
    // Every record again, in upload order (an instance appears once per draw set it is in): one upload
    // of the whole buffer, what an application streaming its instance transforms does.
    mPlan.instancesMoved(scene);
    const std::vector<InstanceRecord>& records = mPlan.records();
    if (!records.empty())
        glNamedBufferSubData(mInstanceBuffer, 0, GLsizeiptr(records.size() * sizeof(InstanceRecord)),
                             records.data());
    mStats.glCalls += 1;
}

void InstancedSubmitter::attachInstances(GLuint vao, GLuint buffer) {
    glVertexArrayVertexBuffer(vao, 1, buffer, 0, sizeof(InstanceRecord));
    glVertexArrayBindingDivisor(vao, 1, 1);
    for (GLuint c = 0; c < 5; ++c) {
        glEnableVertexArrayAttrib(vao, 4 + c);
        glVertexArrayAttribFormat(vao, 4 + c, 4, GL_FLOAT, GL_FALSE, c * sizeof(glm::vec4));
        glVertexArrayAttribBinding(vao, 4 + c, 1);
    }
}

void InstancedSubmitter::drawRun(const SubmissionPlan::Batch& b, uint32_t first, uint32_t count) {
    const GLsizei indices = mBuffers.indexCount(b.mesh);
    glDrawElementsInstancedBaseInstance(GL_TRIANGLES, indices, GL_UNSIGNED_INT, nullptr, GLsizei(count),
                                        first);
    mStats.drawCalls += 1;
    mStats.triangles += uint64_t(indices) / 3 * count;
    mStats.instances += count;
    mStats.glCalls += 1;
}

void InstancedSubmitter::drawKept(DrawSet set, InstanceMask keep) {
    for (const SubmissionPlan::Batch& b : mPlan.batches(set)) {
        // The kept records of the batch as runs: the instance buffer stays as uploaded, a culled
        // instance splits its batch instead of costing an upload. The mesh is bound at its first run.
        bool bound = false;
        // A run splits where the view's back-face decision changes (scenes/BackFaceCulling.h).
        mPlan.forEachKeptRun(b, keep, backFaceCuller().decisions(),
                             [&](uint32_t first, uint32_t count, bool cull) {
                                 if (!bound) {
                                     glBindVertexArray(mBuffers.vao(b.mesh));
                                     mStats.glCalls += 1;
                                     bound = true;
                                 }
                                 setCullFace(cull);
                                 drawRun(b, first, count);
                             });
    }
    glBindVertexArray(0);
    mStats.glCalls += 1;
}

} // namespace sb
