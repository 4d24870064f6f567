#pragma once
// `msm`: moment shadow maps (Peters and Klein 2015, Moment Shadow Mapping, I3D). vsm's three passes and maps
// (techniques/shadowmap/VsmGL.h has the method) with four moments:
//   "depth"    per light the power moments (d, d^2, d^3, d^4) of linear light-space depth d, through the
//              paper's quantisation transform into an RGBA16 unorm layer (`format=unorm16`, 64 bits per
//              texel; the paper's section on quantization) or raw into RGBA32F (`format=float`)
//              (FilterableShadowMaps; shadowmap/moments.frag, shadowmap/msm.glsl);
//   "blur"     vsm's separable Gaussian over the four channels (the transform is affine, so filtering the
//              stored values filters the moments);
//   "lighting" the moments de-quantised, biased by `moment_bias` and the Hamburger four-moment
//              reconstruction of the fraction in front of the receiver (shadowmap/msm.frag).
// Why: two moments (vsm) bound the lit fraction by Chebyshev's inequality, loose for a receiver close
// behind the farther of two occluders (light leaks); four moments determine a distribution of two depths
// exactly, so that case is answered right but for the bias. Point lights need an omni map (`cubemap`,
// `paraboloid`): refused with ExitCode::Unsupported.
#include "techniques/gl/GlTechnique.h"
#include "techniques/gl/LitPrograms.h"
#include "techniques/gl/SeparableBlur.h"
#include "techniques/shadowmap/FilterableShadowMaps.h"
#include "techniques/shadowmap/Msm.h"

namespace sb {

class MsmGL final : public GlTechnique {
public:
    MsmGL();
    void setScene(const Scene& scene) override;
    /// The light fits and the maps' fit to the receivers follow the scene (FilterableShadowMaps).
    void sceneChanged(const Scene& scene, uint32_t) override { mMaps.fits().sceneChanged(scene); }
    void compile(const CompileContext& ctx) override;
    void execute(FrameContext& ctx) override;
    Counters counters() const override { return mCounters; }
    const MapTexels* mapTexels() const override { return &mMaps.fits(); }

private:
    FilterableShadowMaps mMaps{"msm"};
    SeparableBlur mBlur;
    const Program* mDepthProgram = nullptr;
    LitPrograms mLighting; ///< the lighting pass (non-receivers apart where they can be)
    Counters mCounters;
};

} // namespace sb
