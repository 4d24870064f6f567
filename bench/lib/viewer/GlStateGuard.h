#pragma once
// Saves, on construction, the GL state the viewer's own drawing (bench/lib/viewer/Overlay.h,
// bench/lib/viewer/VisibilityView.h) changes, and puts it back on destruction. The harness resets only
// part of the state before each frame (techniques/gl/FrameState.h): a program, vertex array or texture
// left bound by the viewer would be state the next measured frame starts from that a measurement
// without the viewer never has, so the viewer leaves everything as it found it.
#include <array>

#include <epoxy/gl.h>

namespace sb {

class GlStateGuard {
public:
    GlStateGuard();
    ~GlStateGuard();
    GlStateGuard(const GlStateGuard&) = delete;
    GlStateGuard& operator=(const GlStateGuard&) = delete;

private:
    GLint mProgram = 0, mVertexArray = 0, mArrayBuffer = 0, mActiveTexture = 0, mTexture0 = 0;
    GLint mDrawFramebuffer = 0, mReadFramebuffer = 0;
    std::array<GLint, 4> mViewport{};
    GLint mBlendSrcRgb = 0, mBlendDstRgb = 0, mBlendSrcAlpha = 0, mBlendDstAlpha = 0;
    GLint mBlendEquationRgb = 0, mBlendEquationAlpha = 0;
    GLboolean mBlend = GL_FALSE, mDepthTest = GL_FALSE, mCullFace = GL_FALSE, mStencilTest = GL_FALSE,
              mScissorTest = GL_FALSE;
    std::array<GLboolean, 4> mColorMask{};
};

} // namespace sb
