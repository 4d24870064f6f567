#include "techniques/gl/SeparableBlur.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/Error.h"
#include "techniques/GaussianKernel.h"

namespace sb {

namespace {
constexpr GLint kLayerLocation = 0;    // shaders/common/blur.frag
constexpr GLint kExponentLocation = 1; // ...
constexpr GLint kWeightsLocation = 2;  // uWeights[BLUR_RADIUS + 1]

} // namespace

SeparableBlur::~SeparableBlur() {
    release();
    if (mEmptyVao) glDeleteVertexArrays(1, &mEmptyVao);
}

std::vector<float> SeparableBlur::weights(int width) {
    return GaussianKernel::texelIntegral(width);
}

void SeparableBlur::release() {
    if (mFbo) glDeleteFramebuffers(1, &mFbo);
    if (mTexture) glDeleteTextures(1, &mTexture);
    mFbo = mTexture = 0;
    mResolution = 0;
    mFormat = 0;
}

void SeparableBlur::allocate(int resolution, GLenum format) {
    if (resolution == mResolution && format == mFormat) return;
    release();
    // The horizontal pass's result, read with texelFetch only.
    glCreateTextures(GL_TEXTURE_2D, 1, &mTexture);
    glTextureStorage2D(mTexture, 1, format, resolution, resolution);
    glTextureParameteri(mTexture, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(mTexture, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glCreateFramebuffers(1, &mFbo);
    glNamedFramebufferTexture(mFbo, GL_COLOR_ATTACHMENT0, mTexture, 0);
    glNamedFramebufferDrawBuffer(mFbo, GL_COLOR_ATTACHMENT0);
    const GLenum status = glCheckNamedFramebufferStatus(mFbo, GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw Error("blur: intermediate framebuffer incomplete (status 0x" + std::to_string(status) + ")",
                    ExitCode::Failure);
    mResolution = resolution;
    mFormat = format;
}

std::string SeparableBlur::compile(ProgramCache& programs, const Settings& settings) {
    const bool pointSampled = settings.kernel == Kernel::PointSampled;
    if (pointSampled && settings.mode == Mode::LogSpace)
        throw std::invalid_argument("SeparableBlur: the log-space mode takes the texel-integral kernel");
    mSettings = settings;
    mWeights = pointSampled ? std::vector<float>{1.0f} : weights(settings.size);
    mRadius = pointSampled ? std::max(0, settings.size) : int(mWeights.size()) - 1;
    mHorizontal = mVertical = nullptr;
    if (mRadius == 0) {
        release(); // no intermediate needed without a kernel
        return "";
    }
    allocate(settings.resolution, settings.format);
    if (!mEmptyVao) glCreateVertexArrays(1, &mEmptyVao);
    // TexelIntegral, ClampToEdge and Linear are the shader's defaults: no define.
    Defines defines = {{"BLUR_RADIUS", std::to_string(mRadius)}};
    if (pointSampled) defines["BLUR_POINT_SAMPLED"] = "";
    if (settings.border == Border::One) defines["BLUR_OUTSIDE_ONE"] = "";
    if (settings.mode == Mode::LogSpace) defines["LOG_SPACE"] = "";
    mVertical = &programs.get({"common/fullscreen.vert", "common/blur.frag", ""}, defines);
    defines["BLUR_FROM_ARRAY"] = "";
    mHorizontal = &programs.get({"common/fullscreen.vert", "common/blur.frag", ""}, defines);
    return mHorizontal->key() + "|" + mVertical->key();
}

void SeparableBlur::pass(const Program& program, GLuint source, int layer) const {
    program.use();
    // Only the uniforms the program has: setting an inactive location is a GL error.
    if (layer >= 0) glUniform1i(kLayerLocation, layer);
    if (mSettings.mode == Mode::LogSpace) glUniform1f(kExponentLocation, mExponent);
    if (mSettings.kernel == Kernel::TexelIntegral)
        glUniform1fv(kWeightsLocation, GLsizei(mWeights.size()), mWeights.data());
    glBindTextureUnit(0, source);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindTextureUnit(0, 0); // the source may be the next pass's target
}

SeparableBlur::Work SeparableBlur::apply(GLuint array, const std::vector<GLuint>& layerFbos,
                                         const std::vector<uint8_t>& layers) {
    Work work;
    if (!mHorizontal) return work;
    glViewport(0, 0, mResolution, mResolution);
    glDisable(GL_DEPTH_TEST); // full-screen passes: the layer's depth buffer is not touched
    glBindVertexArray(mEmptyVao);
    for (size_t i = 0; i < layerFbos.size() && i < layers.size(); ++i) {
        if (!layers[i]) continue; // a constant layer (no caster) is its own blur
        glBindFramebuffer(GL_FRAMEBUFFER, mFbo);
        pass(*mHorizontal, array, int(i));
        glBindFramebuffer(GL_FRAMEBUFFER, layerFbos[i]);
        pass(*mVertical, mTexture, -1);
        work.passes += 2;
        work.texels += 2.0 * double(mResolution) * mResolution;
    }
    glBindVertexArray(0);
    glEnable(GL_DEPTH_TEST);
    return work;
}

} // namespace sb
