#pragma once
// The render targets of one frame (DESIGN.md section 4): colour (RGBA8, attachment 0), visibility
// (RGBA16F, attachment 1: channel i = light i, 1 lit, 0 shadowed, fractions for soft shadows; float so
// NaN/Inf survive for the numeric checks), depth-stencil (DEPTH24_STENCIL8: stencil for volumes).
// Fragment shaders write `layout(location = 0) out vec4 oColor; layout(location = 1) out vec4 oVis;`.
#include <vector>

#include <epoxy/gl.h>

namespace sb {

constexpr int kMaxLights = 4; ///< one visibility channel per light

class FrameTargets {
public:
    FrameTargets(int width, int height);
    ~FrameTargets();
    FrameTargets(const FrameTargets&) = delete;
    FrameTargets& operator=(const FrameTargets&) = delete;

    int width() const { return mWidth; }
    int height() const { return mHeight; }
    GLuint fbo() const { return mFbo; }
    GLuint colorTexture() const { return mColor; }
    GLuint visibilityTexture() const { return mVisibility; }
    GLuint depthStencilTexture() const { return mDepthStencil; }
    /// Binds the FBO, sets the viewport, enables draw buffers 0 and 1.
    void bind() const;
    /// Clears colour to `clearColor`, visibility to 1 (lit: pixels without geometry are lit), depth to
    /// 1 and stencil to 0.
    void clear(float r, float g, float b) const;
    /// Read-backs (synchronous; for screenshots and tests, never inside timed frames). Rows bottom-up
    /// as GL returns them.
    std::vector<unsigned char> readColorRGBA8() const;
    std::vector<float> readVisibilityRGBA32F() const; ///< 4 floats per pixel
    std::vector<float> readDepth() const;

private:
    int mWidth, mHeight;
    GLuint mFbo = 0, mColor = 0, mVisibility = 0, mDepthStencil = 0;
};

} // namespace sb
