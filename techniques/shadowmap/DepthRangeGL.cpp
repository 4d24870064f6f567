#include "techniques/shadowmap/DepthRangeGL.h"

#include <cstring>

#include <glm/gtc/type_ptr.hpp>

#include "core/Error.h"
#include "techniques/shadowmap/CascadeSplits.h"

namespace sb {

namespace {
constexpr GLint kLightMatrixLocation = 8;         // common/depth.vert's matrix: here the camera's
constexpr GLuint kGroupSide = 16;                 // depth_range.comp's local size in x and y
constexpr uint32_t kClear[2] = {0x7f800000u, 0u}; // +inf bits and 0: nothing covered yet
} // namespace

void DepthRangeGL::compile(ProgramCache& programs, const Defines& submitterDefines) {
    mDepthProgram = &programs.get({"common/depth.vert", "common/depth.frag", ""}, submitterDefines);
    mReduceProgram = &programs.get({.compute = "shadowmap/depth_range.comp"}, {});
    mFrames = 0;
}

void DepthRangeGL::release() {
    if (mFbo) glDeleteFramebuffers(1, &mFbo);
    if (mTexture) glDeleteTextures(1, &mTexture);
    for (size_t i = 0; i < 2; ++i) {
        if (mFences[i]) glDeleteSync(mFences[i]);
        mFences[i] = nullptr;
    }
    if (mBuffers[0]) glDeleteBuffers(2, mBuffers.data());
    mFbo = mTexture = 0;
    mBuffers = {};
    mWidth = mHeight = 0;
}

void DepthRangeGL::allocate(int width, int height) {
    if (width == mWidth && height == mHeight && mTexture) return;
    release();
    glCreateTextures(GL_TEXTURE_2D, 1, &mTexture);
    glTextureStorage2D(mTexture, 1, GL_DEPTH_COMPONENT32F, width, height);
    glTextureParameteri(mTexture, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(mTexture, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glCreateFramebuffers(1, &mFbo);
    glNamedFramebufferTexture(mFbo, GL_DEPTH_ATTACHMENT, mTexture, 0);
    glNamedFramebufferDrawBuffer(mFbo, GL_NONE);
    if (glCheckNamedFramebufferStatus(mFbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw Error("cascaded: the depth pre-pass framebuffer (" + std::to_string(width) + "x" +
                        std::to_string(height) + " GL_DEPTH_COMPONENT32F) is incomplete",
                    ExitCode::Failure);
    glCreateBuffers(2, mBuffers.data());
    for (GLuint b : mBuffers) glNamedBufferStorage(b, sizeof kClear, kClear, GL_DYNAMIC_STORAGE_BIT);
    mWidth = width;
    mHeight = height;
    mFrames = 0;
}

void DepthRangeGL::prePass(const FrameContext& ctx) {
    glBindFramebuffer(GL_FRAMEBUFFER, mFbo);
    glViewport(0, 0, mWidth, mHeight);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    mDepthProgram->use();
    const glm::mat4 viewProj = ctx.proj * ctx.view;
    glUniformMatrix4fv(kLightMatrixLocation, 1, GL_FALSE, glm::value_ptr(viewProj));
    // Every instance: a non-receiver in front of a receiver hides its samples as well.
    ctx.submitter.drawCulled(DrawSet::All, cameraCullView(ctx));
}

void DepthRangeGL::reduce(size_t buffer) {
    glNamedBufferSubData(mBuffers[buffer], 0, sizeof kClear, kClear);
    glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    mReduceProgram->use();
    glBindTextureUnit(0, mTexture);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, mBuffers[buffer]);
    glDispatchCompute((GLuint(mWidth) + kGroupSide - 1) / kGroupSide,
                      (GLuint(mHeight) + kGroupSide - 1) / kGroupSide, 1);
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

glm::vec2 DepthRangeGL::run(const FrameContext& ctx) {
    allocate(ctx.targets.width(), ctx.targets.height());
    const size_t current = size_t(mFrames % 2), previous = 1 - current;
    prePass(ctx);
    reduce(current);
    mProj[current] = ctx.proj;
    const size_t answer = mFrames == 0 ? current : previous;
    ++mFrames;
    mWindow = readWindow(answer);
    if (mWindow.x > mWindow.y) return mWindow; // nothing covered: an empty interval
    return CascadeSplits::viewDepths(mWindow, mProj[answer]);
}

} // namespace sb
