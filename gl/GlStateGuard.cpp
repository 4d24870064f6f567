#include "gl/GlStateGuard.h"

namespace sb {

GlStateGuard::GlStateGuard() {
    glGetIntegerv(GL_CURRENT_PROGRAM, &mProgram);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &mVertexArray);
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &mArrayBuffer);
    glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &mPackBuffer);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &mActiveTexture);
    glActiveTexture(GL_TEXTURE0);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &mTexture0);
    glActiveTexture(GLenum(mActiveTexture));
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &mDrawFramebuffer);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &mReadFramebuffer);
    glGetIntegerv(GL_VIEWPORT, mViewport.data());
    for (size_t i = 0; i < kEnables.size(); ++i) mEnabled[i] = glIsEnabled(kEnables[i]);
    glGetIntegerv(GL_BLEND_SRC_RGB, &mBlendSrcRgb);
    glGetIntegerv(GL_BLEND_DST_RGB, &mBlendDstRgb);
    glGetIntegerv(GL_BLEND_SRC_ALPHA, &mBlendSrcAlpha);
    glGetIntegerv(GL_BLEND_DST_ALPHA, &mBlendDstAlpha);
    glGetIntegerv(GL_BLEND_EQUATION_RGB, &mBlendEquationRgb);
    glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &mBlendEquationAlpha);
    glGetBooleanv(GL_COLOR_WRITEMASK, mColorMask.data());
    glGetBooleanv(GL_DEPTH_WRITEMASK, &mDepthMask);
    for (size_t f = 0; f < mStencil.size(); ++f) {
        const bool back = f == 1;
        Stencil& s = mStencil[f];
        glGetIntegerv(back ? GL_STENCIL_BACK_WRITEMASK : GL_STENCIL_WRITEMASK, &s.writeMask);
        glGetIntegerv(back ? GL_STENCIL_BACK_FUNC : GL_STENCIL_FUNC, &s.func);
        glGetIntegerv(back ? GL_STENCIL_BACK_REF : GL_STENCIL_REF, &s.ref);
        glGetIntegerv(back ? GL_STENCIL_BACK_VALUE_MASK : GL_STENCIL_VALUE_MASK, &s.valueMask);
        glGetIntegerv(back ? GL_STENCIL_BACK_FAIL : GL_STENCIL_FAIL, &s.fail);
        glGetIntegerv(back ? GL_STENCIL_BACK_PASS_DEPTH_FAIL : GL_STENCIL_PASS_DEPTH_FAIL, &s.depthFail);
        glGetIntegerv(back ? GL_STENCIL_BACK_PASS_DEPTH_PASS : GL_STENCIL_PASS_DEPTH_PASS, &s.pass);
    }
    glGetIntegerv(GL_PACK_ALIGNMENT, &mPackAlignment);
}

GlStateGuard::~GlStateGuard() {
    glUseProgram(GLuint(mProgram));
    glBindVertexArray(GLuint(mVertexArray));
    glBindBuffer(GL_ARRAY_BUFFER, GLuint(mArrayBuffer));
    glBindBuffer(GL_PIXEL_PACK_BUFFER, GLuint(mPackBuffer));
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, GLuint(mTexture0));
    glActiveTexture(GLenum(mActiveTexture));
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(mDrawFramebuffer));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(mReadFramebuffer));
    glViewport(mViewport[0], mViewport[1], mViewport[2], mViewport[3]);
    for (size_t i = 0; i < kEnables.size(); ++i) mEnabled[i] ? glEnable(kEnables[i]) : glDisable(kEnables[i]);
    glBlendFuncSeparate(GLenum(mBlendSrcRgb), GLenum(mBlendDstRgb), GLenum(mBlendSrcAlpha),
                        GLenum(mBlendDstAlpha));
    glBlendEquationSeparate(GLenum(mBlendEquationRgb), GLenum(mBlendEquationAlpha));
    glColorMask(mColorMask[0], mColorMask[1], mColorMask[2], mColorMask[3]);
    glDepthMask(mDepthMask);
    for (size_t f = 0; f < mStencil.size(); ++f) {
        const GLenum face = f == 1 ? GL_BACK : GL_FRONT;
        const Stencil& s = mStencil[f];
        glStencilMaskSeparate(face, GLuint(s.writeMask));
        glStencilFuncSeparate(face, GLenum(s.func), s.ref, GLuint(s.valueMask));
        glStencilOpSeparate(face, GLenum(s.fail), GLenum(s.depthFail), GLenum(s.pass));
    }
    glPixelStorei(GL_PACK_ALIGNMENT, mPackAlignment);
}

} // namespace sb
