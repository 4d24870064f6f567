#include "gl/TextureFramebuffer.h"

#include "core/Error.h"

namespace sb {

namespace {
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
    glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return texture;
}

std::string formatName(GLenum f) {
    switch (f) {
    case GL_RGBA8:
        return "RGBA8";
    case GL_RGBA16F:
        return "RGBA16F";
    case GL_RGBA32F:
        return "RGBA32F";
    case GL_R32UI:
        return "R32UI";
    default:
        return "format 0x" + std::to_string(f);
    }
}
} // namespace

TextureFramebuffer::TextureFramebuffer(const std::string& what, int width, int height,
                                       const std::vector<GLenum>& colorFormats)
    : mWidth(width), mHeight(height) {
    if (width <= 0 || height <= 0)
        throw Error(what + ": invalid size " + std::to_string(width) + "x" + std::to_string(height));
    glCreateFramebuffers(1, &mFbo);
    std::string formats;
    for (size_t i = 0; i < colorFormats.size(); ++i) {
        mColors.push_back(createTexture(colorFormats[i], width, height));
        mDrawBuffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
        glNamedFramebufferTexture(mFbo, mDrawBuffers.back(), mColors.back(), 0);
        formats += formatName(colorFormats[i]) + " + ";
    }
    mDepthStencil = createTexture(GL_DEPTH24_STENCIL8, width, height);
    glNamedFramebufferTexture(mFbo, GL_DEPTH_STENCIL_ATTACHMENT, mDepthStencil, 0);
    glNamedFramebufferDrawBuffers(mFbo, GLsizei(mDrawBuffers.size()), mDrawBuffers.data());
    GLenum status = glCheckNamedFramebufferStatus(mFbo, GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        std::string message = what + " " + std::to_string(width) + "x" + std::to_string(height) + " (" +
                              formats + "DEPTH24_STENCIL8) incomplete: " + statusName(status);
        release(); // no destructor runs after a throwing constructor
        throw Error(message, ExitCode::Unsupported);
    }
}

TextureFramebuffer::~TextureFramebuffer() {
    release();
}

void TextureFramebuffer::release() {
    glDeleteFramebuffers(1, &mFbo);
    glDeleteTextures(GLsizei(mColors.size()), mColors.data());
    glDeleteTextures(1, &mDepthStencil);
    mFbo = mDepthStencil = 0;
    mColors.clear();
}

void TextureFramebuffer::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, mFbo);
    glDrawBuffers(GLsizei(mDrawBuffers.size()), mDrawBuffers.data());
    glViewport(0, 0, mWidth, mHeight);
}

void TextureFramebuffer::read(GLenum attachment, GLenum format, GLenum type, void* out) const {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, mFbo);
    if (attachment != GL_NONE) glReadBuffer(attachment);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, mWidth, mHeight, format, type, out);
}

} // namespace sb
