#pragma once
// The separable Gaussian blur of filterable shadow maps (`vsm`, `esm`): a horizontal pass from each
// layer of the map's texture array into one intermediate 2D texture, then a vertical pass from it back
// into the layer (shaders/shadowmap/blur.frag), the two-pass form of a 2D Gaussian (Lauritzen 2007,
// Summed-Area Variance Shadow Maps, GPU Gems 3 ch. 8, section 8.4.1: "a separable Gaussian blur";
// Annen et al. 2008, Exponential Shadow Maps, section 4: the exponential map "can be filtered with a
// separable Gaussian").
//
// The kernel: `width` texels wide, a Gaussian of sigma = width / 4 truncated to [-width / 2, width / 2]
// (two sigma each side, as `projective`'s blur), and each tap's weight the integral of that truncated
// Gaussian over the tap's texel, [k - 0.5, k + 0.5], normalised to sum 1: so every width, odd or even,
// is a kernel exactly `width` texels wide, taps |k| <= width / 2 (integer division). Width 0 and 1 have
// one tap of weight 1: no blur, and apply() does no GL work. The weights are computed here once per
// width and passed to the shader as uniforms.
//
// Two modes (Mode): Linear filters each channel linearly (VSM's moments); LogSpace filters exp(c d) of a
// channel holding depth d and writes back log(sum w_k exp(c d_k)) / c (Salvi 2008, Rendering Filtered
// Shadows with Exponential Shadow Maps, ShaderX6, "log space filtering"), computed as
// m + log(sum w_k exp(c (d_k - m))) / c with m = max_k d_k so that no term exceeds 1 and the sum is at
// least the weight of the largest tap: finite at every exponent.
//
// Texels outside the map read as the nearest edge texel (the sampler's clamp to edge): the filter never
// invents an occluder or a hole at the border.
#include <vector>

#include <epoxy/gl.h>

#include "techniques/gl/GlTechnique.h"
#include "techniques/shadowmap/ShadowMapProperties.h"

namespace sb {

class SeparableBlur {
public:
    enum class Mode { Linear, LogSpace };
    /// The widest kernel the shader is compiled for (the property's maximum).
    static constexpr int kMaxWidth = ShadowMapProperties::kMaxBlurWidth;

    SeparableBlur() = default;
    ~SeparableBlur();
    SeparableBlur(const SeparableBlur&) = delete;
    SeparableBlur& operator=(const SeparableBlur&) = delete;

    /// Weights of taps 0..width/2 (the kernel is symmetric: tap -k has the weight of tap k); they sum to
    /// 1 over all 2 (width/2) + 1 taps. Width 0 gives {1}.
    static std::vector<float> weights(int width);

    /// Programs and the intermediate texture for `width` at `resolution` x `resolution` in `format`
    /// (the map's: GL_RG32F, GL_R32F). Returns the programs' permutation keys ("" at width < 2).
    std::string compile(ProgramCache& programs, Mode mode, int width, int resolution, GLenum format);
    /// Sets the exponent c of the LogSpace mode (ignored in Linear).
    void setExponent(float c) { mExponent = c; }
    /// Blurs each layer i of `array` (through `layerFbos[i]`) for which `layers[i]` is non-zero. Returns
    /// the texels written (two passes per layer), 0 when the kernel has one tap.
    double apply(GLuint array, const std::vector<GLuint>& layerFbos, const std::vector<uint8_t>& layers);
    int radius() const { return int(mWeights.size()) - 1; }

private:
    void allocate(int resolution, GLenum format);
    void release();
    /// One direction from `source` into the bound framebuffer; `layer` < 0: the source is 2D.
    void pass(const Program& program, GLuint source, int layer) const;

    std::vector<float> mWeights{1.0f};
    Mode mMode = Mode::Linear;
    float mExponent = 1.0f;
    GLuint mTexture = 0, mFbo = 0, mEmptyVao = 0;
    int mResolution = 0;
    GLenum mFormat = 0;
    const Program* mHorizontal = nullptr; ///< layer -> intermediate
    const Program* mVertical = nullptr;   ///< intermediate -> layer
};

} // namespace sb
