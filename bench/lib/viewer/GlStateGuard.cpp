#include "bench/lib/viewer/GlStateGuard.h"

namespace sb {

namespace {
void setEnabled(GLenum cap, GLboolean on) {
    on ? glEnable(cap) : glDisable(cap);
}
} // namespace

GlStateGuard::GlStateGuard() {
    glGetIntegerv(GL_CURRENT_PROGRAM, &mProgram);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &mVertexArray);
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &mArrayBuffer);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &mActiveTexture);
    glActiveTexture(GL_TEXTURE0);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &mTexture0);
    glActiveTexture(GLenum(mActiveTexture));
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &mDrawFramebuffer);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &mReadFramebuffer);
    glGetIntegerv(GL_VIEWPORT, mViewport.data());
    glGetIntegerv(GL_BLEND_SRC_RGB, &mBlendSrcRgb);
    glGetIntegerv(GL_BLEND_DST_RGB, &mBlendDstRgb);
    glGetIntegerv(GL_BLEND_SRC_ALPHA, &mBlendSrcAlpha);
    glGetIntegerv(GL_BLEND_DST_ALPHA, &mBlendDstAlpha);
    glGetIntegerv(GL_BLEND_EQUATION_RGB, &mBlendEquationRgb);
    glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &mBlendEquationAlpha);
    mBlend = glIsEnabled(GL_BLEND);
    mDepthTest = glIsEnabled(GL_DEPTH_TEST);
    mCullFace = glIsEnabled(GL_CULL_FACE);
    mStencilTest = glIsEnabled(GL_STENCIL_TEST);
    mScissorTest = glIsEnabled(GL_SCISSOR_TEST);
    glGetBooleanv(GL_COLOR_WRITEMASK, mColorMask.data());
}

GlStateGuard::~GlStateGuard() {
    glUseProgram(GLuint(mProgram));
    glBindVertexArray(GLuint(mVertexArray));
    glBindBuffer(GL_ARRAY_BUFFER, GLuint(mArrayBuffer));
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, GLuint(mTexture0));
    glActiveTexture(GLenum(mActiveTexture));
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(mDrawFramebuffer));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(mReadFramebuffer));
    glViewport(mViewport[0], mViewport[1], mViewport[2], mViewport[3]);
    glBlendFuncSeparate(GLenum(mBlendSrcRgb), GLenum(mBlendDstRgb), GLenum(mBlendSrcAlpha),
                        GLenum(mBlendDstAlpha));
    glBlendEquationSeparate(GLenum(mBlendEquationRgb), GLenum(mBlendEquationAlpha));
    setEnabled(GL_BLEND, mBlend);
    setEnabled(GL_DEPTH_TEST, mDepthTest);
    setEnabled(GL_CULL_FACE, mCullFace);
    setEnabled(GL_STENCIL_TEST, mStencilTest);
    setEnabled(GL_SCISSOR_TEST, mScissorTest);
    glColorMask(mColorMask[0], mColorMask[1], mColorMask[2], mColorMask[3]);
}

} // namespace sb
