#include "techniques/gl/ViewDepthGL.h"

#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "core/Error.h"
#include "techniques/ViewDepth.h"

namespace sb {

namespace {
constexpr GLint kMatrixLocation = 8; // common/depth.vert's matrix (uLightViewProj): here the camera's
} // namespace

void ViewDepthGL::compile(ProgramCache& programs, const Defines& submitterDefines) {
    mProgram = &programs.get({"common/depth.vert", "common/depth.frag", ""}, submitterDefines);
}

void ViewDepthGL::release() {
    if (mBlock) glDeleteBuffers(1, &mBlock);
    mBlock = 0;
    if (mFbo) glDeleteFramebuffers(1, &mFbo);
    if (mTexture) glDeleteTextures(1, &mTexture);
    mFbo = mTexture = 0;
    mWidth = mHeight = 0;
}

void ViewDepthGL::allocate(int width, int height) {
    if (width == mWidth && height == mHeight && mTexture) return;
    release();
    glCreateTextures(GL_TEXTURE_2D, 1, &mTexture);
    glTextureStorage2D(mTexture, 1, GL_DEPTH_COMPONENT32F, width, height);
    glTextureParameteri(mTexture, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(mTexture, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(mTexture, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(mTexture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glCreateFramebuffers(1, &mFbo);
    glNamedFramebufferTexture(mFbo, GL_DEPTH_ATTACHMENT, mTexture, 0);
    glNamedFramebufferDrawBuffer(mFbo, GL_NONE);
    if (glCheckNamedFramebufferStatus(mFbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw Error("view depth pre-pass: its framebuffer (" + std::to_string(width) + "x" +
                        std::to_string(height) + " GL_DEPTH_COMPONENT32F) is incomplete",
                    ExitCode::Failure);
    mWidth = width;
    mHeight = height;
    ++mAllocations;
}

void ViewDepthGL::bindForLighting(const glm::vec4& block) {
    if (!mBlock) {
        glCreateBuffers(1, &mBlock);
        glNamedBufferStorage(mBlock, sizeof block, nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    glNamedBufferSubData(mBlock, 0, sizeof block, &block);
    glBindBufferBase(GL_UNIFORM_BUFFER, kLightingBlock, mBlock);
    glBindTextureUnit(kLightingUnit, mTexture);
}

void ViewDepthGL::unbindForLighting() {
    glBindTextureUnit(kLightingUnit, 0);
    glBindBufferBase(GL_UNIFORM_BUFFER, kLightingBlock, 0);
}

void ViewDepthGL::render(const FrameContext& ctx) {
    allocate(ctx.targets.width(), ctx.targets.height());
    glBindFramebuffer(GL_FRAMEBUFFER, mFbo);
    glViewport(0, 0, mWidth, mHeight);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glClearDepth(double(ViewDepth::kClear));
    glClear(GL_DEPTH_BUFFER_BIT);
    mProgram->use();
    const glm::mat4 viewProj = ctx.proj * ctx.view;
    glUniformMatrix4fv(kMatrixLocation, 1, GL_FALSE, glm::value_ptr(viewProj));
    // Every instance: a non-receiver in front of a receiver hides its samples as well.
    ctx.submitter.drawCulled(DrawSet::All, cameraCullView(ctx));
    mProj = ctx.proj;
}

} // namespace sb
