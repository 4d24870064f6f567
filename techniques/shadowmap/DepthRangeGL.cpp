#include "techniques/shadowmap/DepthRangeGL.h"

#include <cstring>

#include "techniques/ViewDepth.h"

namespace sb {

namespace {
constexpr GLuint kGroupSide = 16;                 // depth_range.comp's local size in x and y
constexpr uint32_t kClear[2] = {0x7f800000u, 0u}; // +inf bits and 0: nothing covered yet
} // namespace

void DepthRangeGL::compile(ProgramCache& programs) {
    mProgram = &programs.get({.compute = "shadowmap/depth_range.comp"}, {});
    mFrames = 0;
}

void DepthRangeGL::release() {
    for (size_t i = 0; i < 2; ++i) {
        if (mFences[i]) glDeleteSync(mFences[i]);
        mFences[i] = nullptr;
    }
    if (mBuffers[0]) glDeleteBuffers(2, mBuffers.data());
    mBuffers = {};
}

void DepthRangeGL::allocate() {
    if (mBuffers[0]) return;
    glCreateBuffers(2, mBuffers.data());
    for (GLuint b : mBuffers) glNamedBufferStorage(b, sizeof kClear, kClear, GL_DYNAMIC_STORAGE_BIT);
}

void DepthRangeGL::reduce(const ViewDepthGL& depth, size_t buffer) {
    glNamedBufferSubData(mBuffers[buffer], 0, sizeof kClear, kClear);
    glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    mProgram->use();
    glBindTextureUnit(0, depth.texture());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, mBuffers[buffer]);
    glDispatchCompute((GLuint(depth.width()) + kGroupSide - 1) / kGroupSide,
                      (GLuint(depth.height()) + kGroupSide - 1) / kGroupSide, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
    glBindTextureUnit(0, 0);
    if (mFences[buffer]) glDeleteSync(mFences[buffer]);
    mFences[buffer] = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
}

glm::vec2 DepthRangeGL::readWindow(size_t buffer) const {
    // Signalled long ago for the last frame's buffer; the first frame's own waits here.
    glClientWaitSync(mFences[buffer], GL_SYNC_FLUSH_COMMANDS_BIT, GLuint64(10'000'000'000));
    uint32_t bits[2];
    glGetNamedBufferSubData(mBuffers[buffer], 0, sizeof bits, bits);
    float window[2];
    std::memcpy(window, bits, sizeof window);
    return {window[0], window[1]};
}

glm::vec2 DepthRangeGL::latestWindowRange() const {
    if (mFrames == 0) return {1.0f, 0.0f};
    return readWindow(size_t((mFrames - 1) % 2));
}

glm::vec2 DepthRangeGL::run(const ViewDepthGL& depth) {
    allocate();
    const size_t current = size_t(mFrames % 2), previous = 1 - current;
    reduce(depth, current);
    mProj[current] = depth.proj();
    const size_t answer = mFrames == 0 ? current : previous;
    ++mFrames;
    mWindow = readWindow(answer);
    if (mWindow.x > mWindow.y) return mWindow; // nothing covered: an empty interval
    return ViewDepth::viewDepths(mWindow, mProj[answer]);
}

} // namespace sb
