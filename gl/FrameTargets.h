#pragma once
// The render targets of one frame (docs/ARCHITECTURE.md, "The technique contract"): colour (RGBA8, attachment
// 0), visibility (RGBA16F, attachment 1: channel i = light i, 1 lit, 0 shadowed, fractions for soft shadows;
// float so NaN/Inf survive for the numeric checks), depth-stencil (DEPTH24_STENCIL8: stencil for volumes).
// Fragment shaders write `layout(location = 0) out vec4 oColor; layout(location = 1) out vec4 oVis;`.
#include <vector>

#include <epoxy/gl.h>

#include "gl/TextureFramebuffer.h"
#include "shading/ShaderLimits.h"

namespace sb {

class FrameTargets {
public:
    FrameTargets(int width, int height);
    FrameTargets(const FrameTargets&) = delete;
    FrameTargets& operator=(const FrameTargets&) = delete;

    int width() const { return mTarget.width(); }
    int height() const { return mTarget.height(); }
    GLuint fbo() const { return mTarget.fbo(); }
    GLuint colorTexture() const { return mTarget.color(0); }
    GLuint visibilityTexture() const { return mTarget.color(1); }
    static constexpr int kColourAttachments = 2; ///< colour, visibility
    GLuint depthStencilTexture() const { return mTarget.depthStencil(); }
    /// Binds the FBO, sets the viewport, enables draw buffer 0 and, while the visibility output is on,
    /// draw buffer 1.
    void bind() const;
    /// The visibility target is the harness's instrument, not part of what an application renders:
    /// timed frames run with it off (an RGBA16F store per lit fragment was ~10% of a shadowmap frame's
    /// instructions on llvmpipe; results/ci/lean-shadow-pass.md), and the frames whose visibility is
    /// read (census, accuracy, images, the viewer) with it on. Default on.
    void setVisibilityOutput(bool on);
    bool visibilityOutput() const { return mVisibilityOn; }
    /// Clears colour to `clearColor`, visibility to 1 (lit: pixels without geometry are lit), depth to
    /// 1 and stencil to 0.
    void clear(float r, float g, float b) const;
    /// Read-backs (synchronous; for screenshots and tests, never inside timed frames). Rows bottom-up
    /// as GL returns them.
    std::vector<unsigned char> readColorRGBA8() const;
    std::vector<float> readVisibilityRGBA32F() const; ///< 4 floats per pixel
    std::vector<float> readDepth() const;

private:
    bool mVisibilityOn = true;
    TextureFramebuffer mTarget;
};

} // namespace sb
