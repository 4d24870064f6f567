#include "gl/FrameTargets.h"

#include <initializer_list>
#include <string>

#include "scenes/Error.h"

namespace sb {
namespace {

constexpr GLenum kDrawBuffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};

const char* statusName(GLenum status) {
    switch (status) {
    case GL_FRAMEBUFFER_UNDEFINED:
        return "GL_FRAMEBUFFER_UNDEFINED";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT:
        return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
        return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER:
        return "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER";
    case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER:
        return "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER";
    case GL_FRAMEBUFFER_UNSUPPORTED:
        return "GL_FRAMEBUFFER_UNSUPPORTED";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE:
        return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
    case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS:
        return "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS";
    default:
        return "unknown framebuffer status";
    }
}

GLuint createTexture(GLenum format, int width, int height) {
    GLuint texture = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &texture);
    glTextureStorage2D(texture, 1, format, width, height);
    // Nearest: these are read texel-exactly (visibility metrics, depth comparisons), never filtered.
    glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return texture;
}

/// Binds `fbo` for reading attachment `buffer` with tightly packed rows and no pack buffer bound.
void prepareRead(GLuint fbo, GLenum buffer) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    if (buffer != GL_NONE) glReadBuffer(buffer);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
}

void deleteObjects(GLuint fbo, std::initializer_list<GLuint> textures) {
    glDeleteFramebuffers(1, &fbo);
    glDeleteTextures(static_cast<GLsizei>(textures.size()), textures.begin());
}

} // namespace

FrameTargets::FrameTargets(int width, int height) : mWidth(width), mHeight(height) {
    if (width <= 0 || height <= 0)
        throw Error("frame targets: invalid size " + std::to_string(width) + "x" + std::to_string(height));
    mColor = createTexture(GL_RGBA8, width, height);
    mVisibility = createTexture(GL_RGBA16F, width, height);
    mDepthStencil = createTexture(GL_DEPTH24_STENCIL8, width, height);
    glCreateFramebuffers(1, &mFbo);
    glNamedFramebufferTexture(mFbo, GL_COLOR_ATTACHMENT0, mColor, 0);
    glNamedFramebufferTexture(mFbo, GL_COLOR_ATTACHMENT1, mVisibility, 0);
    glNamedFramebufferTexture(mFbo, GL_DEPTH_STENCIL_ATTACHMENT, mDepthStencil, 0);
    glNamedFramebufferDrawBuffers(mFbo, 2, kDrawBuffers);
    GLenum status = glCheckNamedFramebufferStatus(mFbo, GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        std::string message = "frame targets " + std::to_string(width) + "x" + std::to_string(height) +
                              " (RGBA8 + RGBA16F + DEPTH24_STENCIL8) incomplete: " + statusName(status);
        deleteObjects(mFbo,
                      {mColor, mVisibility, mDepthStencil}); // no destructor after a throwing constructor
        throw Error(message, ExitCode::Unsupported);
    }
}

FrameTargets::~FrameTargets() {
    deleteObjects(mFbo, {mColor, mVisibility, mDepthStencil});
}

void FrameTargets::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, mFbo);
    glDrawBuffers(2, kDrawBuffers);
    glViewport(0, 0, mWidth, mHeight);
}

void FrameTargets::clear(float r, float g, float b) const {
    bind();
    // glClearBuffer honours write masks and the scissor: a technique that left them off would get a
    // partial clear, so clearing forces them to the defaults (and leaves them so).
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glStencilMask(0xFFu);
    const GLfloat color[] = {r, g, b, 1.0f};
    const GLfloat lit[] = {1.0f, 1.0f, 1.0f, 1.0f};
    glClearBufferfv(GL_COLOR, 0, color);
    glClearBufferfv(GL_COLOR, 1, lit);
    glClearBufferfi(GL_DEPTH_STENCIL, 0, 1.0f, 0);
}

std::vector<unsigned char> FrameTargets::readColorRGBA8() const {
    std::vector<unsigned char> pixels(static_cast<size_t>(mWidth) * mHeight * 4);
    prepareRead(mFbo, GL_COLOR_ATTACHMENT0);
    glReadPixels(0, 0, mWidth, mHeight, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    return pixels;
}

std::vector<float> FrameTargets::readVisibilityRGBA32F() const {
    std::vector<float> pixels(static_cast<size_t>(mWidth) * mHeight * 4);
    prepareRead(mFbo, GL_COLOR_ATTACHMENT1);
    // Float read-back is not clamped (GL_CLAMP_READ_COLOR defaults to FIXED_ONLY), so NaN/Inf survive.
    glReadPixels(0, 0, mWidth, mHeight, GL_RGBA, GL_FLOAT, pixels.data());
    return pixels;
}

std::vector<float> FrameTargets::readDepth() const {
    std::vector<float> depth(static_cast<size_t>(mWidth) * mHeight);
    prepareRead(mFbo, GL_NONE);
    glReadPixels(0, 0, mWidth, mHeight, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    return depth;
}

} // namespace sb
