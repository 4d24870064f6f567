#include "techniques/volume/GpuSilhouettesGL.h"

#include <algorithm>

#include <glm/gtc/type_ptr.hpp>

#include "techniques/volume/SilhouetteInputs.h"

namespace sb {

namespace {
// shaders/volume/silhouette.comp's uniforms and bindings.
constexpr GLint kLightLocation = 1, kFlagsLocation = 3, kFaceCountLocation = 4, kDrawLocation = 5,
                kVertexCountLocation = 6, kFaceBaseLocation = 7, kVertexBaseLocation = 8;
constexpr GLuint kCountBinding = 0, kFacesBinding = 1, kVerticesBinding = 2, kCommandsBinding = 3;
/// volume/extrude.vert under PULLED: the caster mesh's doubled vertex buffer.
constexpr GLuint kDoubledBinding = 4;
constexpr GLuint kLocalSize = 64;
constexpr size_t kCommandWords = 4; ///< glDrawArraysIndirect's command
} // namespace

GpuSilhouettesGL::~GpuSilhouettesGL() {
    release();
}

void GpuSilhouettesGL::release() {
    if (mCount) glDeleteBuffers(1, &mCount);
    mCount = 0;
    if (mVertices) glDeleteBuffers(1, &mVertices);
    if (mCommands) glDeleteBuffers(1, &mCommands);
    if (mVao) glDeleteVertexArrays(1, &mVao);
    mVertices = mCommands = mVao = 0;
    mVertexCapacity = mCommandCapacity = 0;
}

void GpuSilhouettesGL::create(bool compute) {
    release();
    glCreateBuffers(1, &mCount);
    const GLuint zero = 0;
    glNamedBufferStorage(mCount, sizeof(GLuint), &zero, GL_DYNAMIC_STORAGE_BIT);
    if (!compute) return;
    glCreateBuffers(1, &mVertices);
    glCreateBuffers(1, &mCommands);
    reserve(mVertices, mVertexCapacity, sizeof(uint32_t));
    reserve(mCommands, mCommandCapacity, kCommandWords * sizeof(uint32_t));
    // No vertex input: extrude.vert under PULLED fetches its vertex from storage buffers.
    glCreateVertexArrays(1, &mVao);
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
    // Each caster's region holds the most its faces can build; its command starts with no vertices.
    mCommandData.assign(std::max<size_t>(1, draws.size()) * kCommandWords, 0u);
    size_t first = 0;
    for (size_t i = 0; i < draws.size(); ++i) {
        mCommandData[i * kCommandWords + 1] = 1; // instanceCount
        mCommandData[i * kCommandWords + 2] = uint32_t(first);
        first +=
            SilhouetteInputs::kMaxVerticesPerFace * buffers.mesh(draws[i].caster->mesh).mesh->faceCount();
    }
    reserve(mVertices, mVertexCapacity, std::max<size_t>(1, first) * sizeof(uint32_t));
    reserve(mCommands, mCommandCapacity, mCommandData.size() * sizeof(uint32_t));
    glNamedBufferSubData(mCommands, 0, GLsizeiptr(mCommandData.size() * sizeof(uint32_t)),
                         mCommandData.data());
    program.use();
    glUniform1ui(kFaceBaseLocation, 0);   // one face buffer per mesh
    glUniform1ui(kVertexBaseLocation, 0); // and one doubled buffer
    bindCount();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kVerticesBinding, mVertices);
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
    // The vertex shader reads the entries, the indirect draws the counts; the next light's upload of
    // the commands comes after these atomics.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, mCommands);
}

void GpuSilhouettesGL::bindCaster(GLuint doubled) const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kDoubledBinding, doubled);
}

void GpuSilhouettesGL::drawIndirect(size_t i) const {
    glDrawArraysIndirect(GL_TRIANGLES, reinterpret_cast<const void*>(i * kCommandWords * sizeof(uint32_t)));
}

} // namespace sb
