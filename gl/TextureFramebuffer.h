#pragma once
// An FBO with N colour textures of given formats (attachments 0..N-1, all enabled as draw buffers)
// and a DEPTH24_STENCIL8 texture: what FrameTargets and the reference's G-buffer both render into.
// Textures are NEAREST/CLAMP: they are read texel-exactly, never filtered.
#include <string>
#include <vector>

#include <epoxy/gl.h>

namespace sb {

/// An immutable single-level 2D texture of `format`, NEAREST-filtered and clamped to its edge: a
/// render target read texel-exactly (this class's attachments, the floor passes of bench/floors/).
GLuint createTexture(GLenum format, int width, int height);

class TextureFramebuffer {
public:
    /// Throws sb::Error(ExitCode::Unsupported) naming `what`, the size, the formats and the status
    /// when the FBO is incomplete; throws BadInput for a non-positive size. Needs a current context.
    TextureFramebuffer(const std::string& what, int width, int height,
                       const std::vector<GLenum>& colorFormats);
    ~TextureFramebuffer();
    TextureFramebuffer(const TextureFramebuffer&) = delete;
    TextureFramebuffer& operator=(const TextureFramebuffer&) = delete;

    int width() const { return mWidth; }
    int height() const { return mHeight; }
    GLuint fbo() const { return mFbo; }
    GLuint color(size_t i) const { return mColors[i]; }
    GLuint depthStencil() const { return mDepthStencil; }
    /// Binds the FBO as the draw framebuffer with its enabled colour attachments (all, unless
    /// setDrawBufferEnabled turned one off), and the viewport.
    void bind() const;
    /// Enables or disables colour attachment `i` as a draw buffer (GL_NONE: writes and clears of it are
    /// discarded, and the driver neither stores nor blends it). Takes effect at the next bind().
    void setDrawBufferEnabled(size_t i, bool enabled);
    /// glReadPixels of the whole attachment (GL_NONE: depth) with tight packing and no pack buffer.
    void read(GLenum attachment, GLenum format, GLenum type, void* out) const;

private:
    void release();
    int mWidth, mHeight;
    GLuint mFbo = 0, mDepthStencil = 0;
    std::vector<GLuint> mColors;
    std::vector<GLenum> mDrawBuffers;
};

} // namespace sb
