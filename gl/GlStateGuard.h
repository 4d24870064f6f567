#pragma once
// Saves, on construction, the GL state that drawing outside a technique's frame changes, and puts it
// back on destruction (also when an exception unwinds the scope). Its users draw into the same context
// the harness measures in: the viewer's overlay and visibility view (bench/lib/viewer/Overlay.h,
// bench/lib/viewer/VisibilityView.h), after each frame, and `occluder`'s texture bake
// (techniques/occluder/OccluderTextures.h), at setup. The harness resets only part of the state before
// each frame (techniques/gl/FrameState.h): a program, vertex array, texture, framebuffer or test left
// changed by them would be state the next measured frame starts from that a run without them never has,
// so each leaves everything as it found it.
//
// What is saved, the union of what those users change:
//   bindings   the program, the vertex array, GL_ARRAY_BUFFER, GL_PIXEL_PACK_BUFFER, the active texture
//              unit and unit 0's GL_TEXTURE_2D, the draw and read framebuffers;
//   viewport   the viewport;
//   enables    GL_BLEND, GL_DEPTH_TEST, GL_CULL_FACE, GL_STENCIL_TEST, GL_SCISSOR_TEST, GL_CLIP_DISTANCE0;
//   blending   the separate blend functions and equations;
//   writes     the colour and depth write masks;
//   stencil    front and back: write mask, function, reference, value mask and the three operations;
//   pixels     GL_PACK_ALIGNMENT.
// A user that changes anything else saves it itself.
#include <array>

#include <epoxy/gl.h>

namespace sb {

class GlStateGuard {
public:
    /// Needs a current context; reads the state listed above.
    GlStateGuard();
    /// Restores the state read by the constructor.
    ~GlStateGuard();
    GlStateGuard(const GlStateGuard&) = delete;
    GlStateGuard& operator=(const GlStateGuard&) = delete;

private:
    static constexpr std::array<GLenum, 6> kEnables = {GL_BLEND,        GL_DEPTH_TEST,   GL_CULL_FACE,
                                                       GL_STENCIL_TEST, GL_SCISSOR_TEST, GL_CLIP_DISTANCE0};
    struct Stencil {
        GLint writeMask = 0, func = 0, ref = 0, valueMask = 0, fail = 0, depthFail = 0, pass = 0;
    };

    GLint mProgram = 0, mVertexArray = 0, mArrayBuffer = 0, mPackBuffer = 0, mActiveTexture = 0,
          mTexture0 = 0;
    GLint mDrawFramebuffer = 0, mReadFramebuffer = 0;
    std::array<GLint, 4> mViewport{};
    std::array<GLboolean, kEnables.size()> mEnabled{};
    GLint mBlendSrcRgb = 0, mBlendDstRgb = 0, mBlendSrcAlpha = 0, mBlendDstAlpha = 0;
    GLint mBlendEquationRgb = 0, mBlendEquationAlpha = 0;
    std::array<GLboolean, 4> mColorMask{};
    GLboolean mDepthMask = GL_TRUE;
    std::array<Stencil, 2> mStencil{}; ///< front, back
    GLint mPackAlignment = 4;
};

} // namespace sb
