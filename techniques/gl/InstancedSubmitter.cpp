#include "techniques/gl/InstancedSubmitter.h"

#include <algorithm>

#include <glm/glm.hpp>

namespace sb {

namespace {
constexpr DrawSet kSets[kDrawSetCount] = {DrawSet::All, DrawSet::Casters, DrawSet::Receivers,
                                          DrawSet::NonCasters, DrawSet::NonReceivers};
} // namespace

InstancedSubmitter::~InstancedSubmitter() {
    release();
}

void InstancedSubmitter::release() {
    if (mInstanceBuffer) glDeleteBuffers(1, &mInstanceBuffer);
    mInstanceBuffer = 0;
}

void InstancedSubmitter::upload(const Scene& scene) {
    release();
    mScene = &scene;
    mBuffers.upload(scene);
    // One buffer holding, per draw set and mesh, that set's instances contiguously.
    std::vector<InstanceRecord>& records = mRecords;
    records.clear();
    mRecordInstance.clear();
    for (size_t s = 0; s < kDrawSetCount; ++s) {
        mBatches[s].clear();
        for (uint32_t m = 0; m < scene.meshes.size(); ++m) {
            Batch b{m, uint32_t(records.size()), 0};
            for (uint32_t i = 0; i < scene.instances.size(); ++i) {
                const Instance& inst = scene.instances[i];
                if (inst.mesh != m || !inDrawSet(inst, kSets[s])) continue;
                records.push_back({inst.model, glm::vec4(inst.color, shadowSignedId(inst))});
                mRecordInstance.push_back(i);
                ++b.count;
            }
            if (b.count) mBatches[s].push_back(b);
        }
    }
    glCreateBuffers(1, &mInstanceBuffer);
    // Dynamic storage: a scene in motion rewrites the records of its moving casters every frame.
    glNamedBufferStorage(mInstanceBuffer,
                         GLsizeiptr(std::max<size_t>(1, records.size()) * sizeof(InstanceRecord)),
                         records.empty() ? nullptr : records.data(), GL_DYNAMIC_STORAGE_BIT);
    // A VAO per mesh: the shared mesh buffers at binding 0, the instance buffer at binding 1.
    for (size_t m = 0; m < scene.meshes.size(); ++m) attachInstances(mBuffers.vao(m), mInstanceBuffer);
}

void InstancedSubmitter::instancesMoved(const Scene& scene) {
    // Every record again, in upload order (an instance appears once per draw set it is in): one upload
    // of the whole buffer, what an application streaming its instance transforms does.
    for (size_t r = 0; r < mRecords.size(); ++r)
        mRecords[r].model = scene.instances[mRecordInstance[r]].model;
    if (!mRecords.empty())
        glNamedBufferSubData(mInstanceBuffer, 0, GLsizeiptr(mRecords.size() * sizeof(InstanceRecord)),
                             mRecords.data());
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

void InstancedSubmitter::drawRun(const Batch& b, uint32_t first, uint32_t count) {
    const GLsizei indices = mBuffers.indexCount(b.mesh);
    glDrawElementsInstancedBaseInstance(GL_TRIANGLES, indices, GL_UNSIGNED_INT, nullptr, GLsizei(count),
                                        first);
    mStats.drawCalls += 1;
    mStats.triangles += uint64_t(indices) / 3 * count;
    mStats.instances += count;
    mStats.glCalls += 1;
}

void InstancedSubmitter::drawKept(DrawSet set, InstanceMask keep) {
    for (const Batch& b : mBatches[size_t(set)]) {
        // The kept records of the batch as runs [first, end): the instance buffer stays as uploaded,
        // a culled instance splits its batch instead of costing an upload.
        bool bound = false;
        for (uint32_t r = b.first, end = b.first + b.count; r < end;) {
            if (!keptBy(keep, mRecordInstance[r])) {
                ++r;
                continue;
            }
            uint32_t runEnd = r + 1;
            while (runEnd < end && keptBy(keep, mRecordInstance[runEnd])) ++runEnd;
            if (!bound) {
                glBindVertexArray(mBuffers.vao(b.mesh));
                mStats.glCalls += 1;
                bound = true;
            }
            drawRun(b, r, runEnd - r);
            r = runEnd;
        }
    }
    glBindVertexArray(0);
    mStats.glCalls += 1;
}

} // namespace sb
