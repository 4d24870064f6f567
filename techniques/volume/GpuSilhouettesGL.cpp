#include "techniques/volume/GpuSilhouettesGL.h"

#include <algorithm>

#include <glm/gtc/type_ptr.hpp>

#include "techniques/volume/SilhouetteInputs.h"

namespace sb {

namespace {
// shaders/volume/silhouette.comp's uniforms and bindings.
constexpr GLint kLightLocation = 1, kFlagsLocation = 3, kFaceCountLocation = 4, kDrawLocation = 5,
                kVertexCountLocation = 6, kFaceBaseLocation = 7;
constexpr GLuint kCountBinding = 0, kFacesBinding = 1, kIndicesBinding = 2, kCommandsBinding = 3;
constexpr GLuint kLocalSize = 64;
constexpr size_t kCommandWords = 5; ///< glDrawElementsIndirect's command
} // namespace

GpuSilhouettesGL::~GpuSilhouettesGL() {
    release();
}

void GpuSilhouettesGL::release() {
    if (mCount) glDeleteBuffers(1, &mCount);
    mCount = 0;
    if (mIndices) glDeleteBuffers(1, &mIndices);
    if (mCommands) glDeleteBuffers(1, &mCommands);
    mIndices = mCommands = 0;
    mIndexCapacity = mCommandCapacity = 0;
}

void GpuSilhouettesGL::create(VolumeMeshBuffers& buffers, bool compute) {
    release();
    glCreateBuffers(1, &mCount);
    const GLuint zero = 0;
    glNamedBufferStorage(mCount, sizeof(GLuint), &zero, GL_DYNAMIC_STORAGE_BIT);
    if (!compute) return;
    glCreateBuffers(1, &mIndices);
    glCreateBuffers(1, &mCommands);
    reserve(mIndices, mIndexCapacity, 4);
    reserve(mCommands, mCommandCapacity, kCommandWords * sizeof(uint32_t));
    buffers.setElementBuffer(mIndices);
}

void GpuSilhouettesGL::reserve(GLuint buffer, size_t& capacity, size_t bytes) {
    if (bytes <= capacity) return;
    // Geometric growth: a light with a few more casters in range does not reallocate every frame.
    capacity = std::max(bytes, capacity * 2);
    glNamedBufferData(buffer, GLsizeiptr(capacity), nullptr, GL_DYNAMIC_DRAW);
}

void GpuSilhouettesGL::beginFrame() {
    // Last frame's shader atomics are ordered before this clear.
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    const GLuint zero = 0;
    glClearNamedBufferSubData(mCount, GL_R32UI, 0, sizeof(GLuint), GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

void GpuSilhouettesGL::bindCount() const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kCountBinding, mCount);
}

double GpuSilhouettesGL::readTriangles() const {
    if (!mCount) return 0;
    // The barrier makes the shaders' atomic additions visible to the read, which waits for them.
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    GLuint value = 0;
    glGetNamedBufferSubData(mCount, 0, sizeof(GLuint), &value);
    return double(value);
}

void GpuSilhouettesGL::extract(const std::vector<VolumePlanner::Draw>& draws,
                               const VolumeMeshBuffers& buffers, const Program& program) {
    // Each caster's region holds the most its faces can build; its command starts with no indices.
    mCommandData.assign(std::max<size_t>(1, draws.size()) * kCommandWords, 0u);
    size_t first = 0;
    for (size_t i = 0; i < draws.size(); ++i) {
        mCommandData[i * kCommandWords + 1] = 1; // instanceCount
        mCommandData[i * kCommandWords + 2] = uint32_t(first);
        first += SilhouetteInputs::kMaxIndicesPerFace * buffers.mesh(draws[i].caster->mesh).mesh->faceCount();
    }
    reserve(mIndices, mIndexCapacity, std::max<size_t>(1, first) * sizeof(uint32_t));
    reserve(mCommands, mCommandCapacity, mCommandData.size() * sizeof(uint32_t));
    glNamedBufferSubData(mCommands, 0, GLsizeiptr(mCommandData.size() * sizeof(uint32_t)),
                         mCommandData.data());
    program.use();
    glUniform1ui(kFaceBaseLocation, 0); // one face buffer per mesh
    bindCount();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kIndicesBinding, mIndices);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kCommandsBinding, mCommands);
    for (size_t i = 0; i < draws.size(); ++i) {
        const VolumePlanner::Draw& d = draws[i];
        const VolumeMeshBuffers::Gpu& gpu = buffers.mesh(d.caster->mesh);
        const GLuint faces = GLuint(gpu.mesh->faceCount());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kFacesBinding, gpu.faceBuffer);
        glUniform4fv(kLightLocation, 1, glm::value_ptr(d.lightObject));
        glUniform1ui(kFlagsLocation, d.gpuFlags);
        glUniform1ui(kFaceCountLocation, faces);
        glUniform1ui(kDrawLocation, GLuint(i));
        glUniform1ui(kVertexCountLocation, gpu.mesh->vertexCount());
        glDispatchCompute((faces + kLocalSize - 1) / kLocalSize, 1, 1);
    }
    // The indices feed the vertex fetch, the counts the indirect draws; the next light's upload of
    // the commands comes after these atomics.
    glMemoryBarrier(GL_ELEMENT_ARRAY_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, mCommands);
}

void GpuSilhouettesGL::drawIndirect(size_t i) const {
    glDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT,
                           reinterpret_cast<const void*>(i * kCommandWords * sizeof(uint32_t)));
}

} // namespace sb
