#include "gl/FrameTargets.h"

#include <string>

#include "core/Error.h"

namespace sb {

FrameTargets::FrameTargets(int width, int height)
    : mTarget("frame targets", width, height, {GL_RGBA8, GL_RGBA16F}) {}

void FrameTargets::setVisibilityOutput(bool on) {
    mVisibilityOn = on;
    mTarget.setDrawBufferEnabled(1, on);
}

void FrameTargets::bind() const {
    mTarget.bind();
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
    std::vector<unsigned char> pixels(size_t(width()) * size_t(height()) * 4);
    mTarget.read(GL_COLOR_ATTACHMENT0, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    return pixels;
}

std::vector<float> FrameTargets::readVisibilityRGBA32F() const {
    std::vector<float> pixels(size_t(width()) * size_t(height()) * 4);
    // Float read-back is not clamped (GL_CLAMP_READ_COLOR defaults to FIXED_ONLY), so NaN/Inf survive.
    mTarget.read(GL_COLOR_ATTACHMENT1, GL_RGBA, GL_FLOAT, pixels.data());
    return pixels;
}

std::vector<float> FrameTargets::readDepth() const {
    std::vector<float> depth(size_t(width()) * size_t(height()));
    mTarget.read(GL_NONE, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    return depth;
}

} // namespace sb
