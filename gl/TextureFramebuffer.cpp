#include "gl/TextureFramebuffer.h"

#include "core/Error.h"
#include "core/NameTable.h"

namespace sb {

namespace {
constexpr Named<GLenum> kStatusNames[] = {
    {GL_FRAMEBUFFER_UNDEFINED, "GL_FRAMEBUFFER_UNDEFINED"},
    {GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT, "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT"},
    {GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT, "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT"},
    {GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER, "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER"},
    {GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER, "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER"},
    {GL_FRAMEBUFFER_UNSUPPORTED, "GL_FRAMEBUFFER_UNSUPPORTED"},
    {GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE, "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE"},
    {GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS, "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS"},
};
constexpr NameTable kStatuses{kStatusNames};

const char* statusName(GLenum status) {
    return kStatuses.name(status, "unknown framebuffer status");
}

constexpr Named<GLenum> kFormatNames[] = {
    {GL_RGBA8, "RGBA8"},
    {GL_RGBA16F, "RGBA16F"},
    {GL_RGBA32F, "RGBA32F"},
    {GL_R32UI, "R32UI"},
};
constexpr NameTable kFormats{kFormatNames};

std::string formatName(GLenum f) {
    const Named<GLenum>* e = kFormats.find(f);
    return e ? e->name : "format 0x" + std::to_string(f);
}
} // namespace

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

void TextureFramebuffer::setDrawBufferEnabled(size_t i, bool enabled) {
    mDrawBuffers[i] = enabled ? GLenum(GL_COLOR_ATTACHMENT0 + i) : GLenum(GL_NONE);
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
