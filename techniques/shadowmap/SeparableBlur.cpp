#include "techniques/shadowmap/SeparableBlur.h"

#include <algorithm>
#include <cmath>

#include "core/Error.h"

namespace sb {

namespace {
constexpr GLint kLayerLocation = 0;    // shaders/shadowmap/blur.frag
constexpr GLint kExponentLocation = 1; // ...
constexpr GLint kWeightsLocation = 2;  // uWeights[BLUR_RADIUS + 1]

/// The Gaussian's integral from 0 to x, for sigma (the erf form of its CDF, minus one half).
double gaussianIntegral(double x, double sigma) {
    return 0.5 * std::erf(x / (sigma * std::sqrt(2.0)));
}
} // namespace

SeparableBlur::~SeparableBlur() {
    release();
    if (mEmptyVao) glDeleteVertexArrays(1, &mEmptyVao);
}

std::vector<float> SeparableBlur::weights(int width) {
    if (width < 2) return {1.0f};
    const int radius = width / 2;
    const double half = 0.5 * width, sigma = 0.25 * width;
    std::vector<double> w(size_t(radius) + 1);
    double total = 0.0;
    for (int k = 0; k <= radius; ++k) {
        const double a = std::max(k - 0.5, -half), b = std::min(k + 0.5, half);
        w[size_t(k)] = gaussianIntegral(b, sigma) - gaussianIntegral(a, sigma);
        total += k == 0 ? w[0] : 2.0 * w[size_t(k)];
    }
    std::vector<float> out;
    for (double v : w) out.push_back(float(v / total));
    return out;
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

std::string SeparableBlur::compile(ProgramCache& programs, Mode mode, int width, int resolution,
                                   GLenum format) {
    mWeights = weights(width);
    mMode = mode;
    mHorizontal = mVertical = nullptr;
    if (radius() == 0) {
        release(); // no intermediate needed without a kernel
        return "";
    }
    allocate(resolution, format);
    if (!mEmptyVao) glCreateVertexArrays(1, &mEmptyVao);
    Defines defines = {{"BLUR_RADIUS", std::to_string(radius())}};
    if (mode == Mode::LogSpace) defines["LOG_SPACE"] = "";
    mVertical = &programs.get({"common/fullscreen.vert", "shadowmap/blur.frag", ""}, defines);
    defines["BLUR_FROM_ARRAY"] = "";
    mHorizontal = &programs.get({"common/fullscreen.vert", "shadowmap/blur.frag", ""}, defines);
    return mHorizontal->key() + "|" + mVertical->key();
}

void SeparableBlur::pass(const Program& program, GLuint source, int layer) const {
    program.use();
    // Only the uniforms the program has: setting an inactive location is a GL error.
    if (layer >= 0) glUniform1i(kLayerLocation, layer);
    if (mMode == Mode::LogSpace) glUniform1f(kExponentLocation, mExponent);
    glUniform1fv(kWeightsLocation, GLsizei(mWeights.size()), mWeights.data());
    glBindTextureUnit(0, source);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindTextureUnit(0, 0); // the source may be the next pass's target
}

double SeparableBlur::apply(GLuint array, const std::vector<GLuint>& layerFbos,
                            const std::vector<uint8_t>& layers) {
    if (!mHorizontal) return 0.0;
    glViewport(0, 0, mResolution, mResolution);
    glDisable(GL_DEPTH_TEST); // full-screen passes: the layer's depth buffer is not touched
    glBindVertexArray(mEmptyVao);
    double texels = 0.0;
    for (size_t i = 0; i < layerFbos.size() && i < layers.size(); ++i) {
        if (!layers[i]) continue; // a constant layer (no caster) is its own blur
        glBindFramebuffer(GL_FRAMEBUFFER, mFbo);
        pass(*mHorizontal, array, int(i));
        glBindFramebuffer(GL_FRAMEBUFFER, layerFbos[i]);
        pass(*mVertical, mTexture, -1);
        texels += 2.0 * double(mResolution) * mResolution;
    }
    glBindVertexArray(0);
    glEnable(GL_DEPTH_TEST);
    return texels;
}

} // namespace sb
