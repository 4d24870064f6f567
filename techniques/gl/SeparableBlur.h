#pragma once
// The separable Gaussian blur of the techniques that filter a texture array layer by layer: a horizontal
// pass from each layer into one intermediate 2D texture, then a vertical pass from it back into the
// layer (shaders/common/blur.frag), the two-pass form of a 2D Gaussian. Its users are the filterable
// shadow maps (`vsm`, `esm`: Lauritzen 2007, Summed-Area Variance Shadow Maps, GPU Gems 3 ch. 8, section
// 8.4.1: "a separable Gaussian blur"; Annen et al. 2008, Exponential Shadow Maps, section 4: the
// exponential map "can be filtered with a separable Gaussian") and `projective` (the slides' "blur the
// texture for a fake effect"). It lives in techniques/gl/ because no technique folder may include
// another's.
//
// The users filter differently, and each keeps its own images, so the blur takes its permutation as
// Settings:
//
// Kernel::TexelIntegral (`vsm`, `esm`): `size` is the kernel's width in texels, a Gaussian of
// sigma = width / 4 truncated to [-width / 2, width / 2] (two sigma each side), each tap's weight the
// integral of that truncated Gaussian over the tap's texel, [k - 0.5, k + 0.5], normalised to sum 1: so
// every width, odd or even, is a kernel exactly `width` texels wide, taps |k| <= width / 2 (integer
// division). Width 0 and 1 have one tap: no blur. The weights are computed here once per width and passed
// to the shader as uniforms.
// Kernel::PointSampled (`projective`): `size` is the radius r, taps |k| <= r, each weighted by the
// Gaussian's value exp(-k^2 / (2 sigma^2)) at the tap, sigma = r / 2, computed in the shader, the sum
// divided by the sum of the weights. Radius 0 is no blur. It filters the first channel only (written to
// all four), which is all `projective`'s R8 texture has.
//
// Mode::Linear filters each channel linearly (VSM's moments, projective's silhouette); Mode::LogSpace
// (TexelIntegral only) filters exp(c d) of a channel holding depth d and writes back
// log(sum w_k exp(c d_k)) / c (Salvi 2008, Rendering Filtered Shadows with Exponential Shadow Maps,
// ShaderX6, "log space filtering"), computed as m + log(sum w_k exp(c (d_k - m))) / c with m = max_k d_k
// so that no term exceeds 1 and the sum is at least the weight of the largest tap: finite at every
// exponent.
//
// Border::ClampToEdge: texels outside the texture read as the nearest edge texel (the sampler's clamp to
// edge), so the filter never invents an occluder or a hole at the border (`vsm`, `esm`). Border::One:
// they read 1, lit, as the white border colour `projective` samples its texture with.
//
// A blur with one tap does no GL work: compile() makes no program and apply() returns at once.
#include <string>
#include <vector>

#include <epoxy/gl.h>

#include "gl/ProgramCache.h"

namespace sb {

class SeparableBlur {
public:
    enum class Kernel { TexelIntegral, PointSampled };
    enum class Mode { Linear, LogSpace };
    enum class Border { ClampToEdge, One };

    /// One blur's permutation and target (the header above says what each choice computes).
    struct Settings {
        Kernel kernel = Kernel::TexelIntegral;
        int size = 0; ///< TexelIntegral: the width in texels; PointSampled: the radius
        Mode mode = Mode::Linear;
        Border border = Border::ClampToEdge;
        int resolution = 0; ///< the layers' width and height
        GLenum format = 0;  ///< the layers' format, the intermediate's too (GL_RG32F, GL_R32F, GL_R8)
    };
    /// What one apply() did: the passes drawn (two per blurred layer) and the texels they wrote.
    struct Work {
        int passes = 0;
        double texels = 0.0;
    };

    SeparableBlur() = default;
    ~SeparableBlur();
    SeparableBlur(const SeparableBlur&) = delete;
    SeparableBlur& operator=(const SeparableBlur&) = delete;

    /// Kernel::TexelIntegral's weights for `width`: taps 0..width/2 (the kernel is symmetric: tap -k has
    /// the weight of tap k); they sum to 1 over all 2 (width/2) + 1 taps. Width 0 gives {1}. The same
    /// floats as the Vulkan blur's (techniques/GaussianKernel.h computes both).
    static std::vector<float> weights(int width);

    /// Programs and the intermediate texture for `settings`. Returns the programs' permutation keys
    /// (horizontal|vertical; "" for a one-tap kernel). Throws std::invalid_argument for LogSpace with
    /// the PointSampled kernel (not built).
    std::string compile(ProgramCache& programs, const Settings& settings);
    /// Sets the exponent c of the LogSpace mode (ignored in Linear).
    void setExponent(float c) { mExponent = c; }
    /// Blurs each layer i of the 2D array texture `array` (through `layerFbos[i]`, which renders into
    /// it) for which `layers[i]` is non-zero. Leaves the depth test enabled and no vertex array, texture
    /// or program of its own bound.
    Work apply(GLuint array, const std::vector<GLuint>& layerFbos, const std::vector<uint8_t>& layers);
    /// Taps each side of the centre; 0 = no blur.
    int radius() const { return mRadius; }

private:
    void allocate(int resolution, GLenum format);
    void release();
    /// One direction from `source` into the bound framebuffer; `layer` < 0: the source is 2D.
    void pass(const Program& program, GLuint source, int layer) const;

    Settings mSettings;
    int mRadius = 0;
    std::vector<float> mWeights{1.0f}; ///< TexelIntegral's, taps 0..mRadius
    float mExponent = 1.0f;
    GLuint mTexture = 0, mFbo = 0, mEmptyVao = 0;
    int mResolution = 0;
    GLenum mFormat = 0;
    const Program* mHorizontal = nullptr; ///< layer -> intermediate
    const Program* mVertical = nullptr;   ///< intermediate -> layer
};

} // namespace sb
