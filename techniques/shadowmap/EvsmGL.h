#pragma once
// `evsm`: exponential variance shadow maps (Lauritzen and McCool 2008, Layered Variance Shadow Maps, GI, the
// section on the exponential warp; Lauritzen 2007, Summed-Area Variance Shadow Maps, GPU Gems 3 ch. 8, for
// the variance shadow maps it builds on). vsm's three passes and maps (techniques/shadowmap/VsmGL.h has the
// method) over warped depth:
//   "depth"    per light the moments of the warps w+ = exp(c+ d) and, with `components=4`, w- = -exp(-c- d)
//              of linear light-space depth d into an RG32F (2) or RGBA32F (4) array layer
//              (FilterableShadowMaps; shadowmap/moments.frag, shadowmap/evsm.glsl);
//   "blur"     vsm's separable Gaussian over every channel (the warped moments filter linearly);
//   "lighting" Chebyshev's bound in each warped space, the smaller of the two, then vsm's light-bleeding
//              reduction (shadowmap/evsm.frag).
// Why: the exponential warp spreads the depths behind an occluder apart (exp(c+ t) - exp(c+ d) grows with
// exp(c+ d)), so the two-depth case where vsm's bound leaks (a receiver close behind the farther of two
// occluders) reads far from the filter's mean in the warped space and gets a small bound. The exponents
// are compile-time constants of the shaders (EVSM_EXPONENTS): changing them recompiles. Point lights need
// an omni map (`cubemap`, `paraboloid`): refused with ExitCode::Unsupported.
#include "techniques/gl/GlTechnique.h"
#include "techniques/gl/LitPrograms.h"
#include "techniques/gl/SeparableBlur.h"
#include "techniques/shadowmap/Evsm.h"
#include "techniques/shadowmap/FilterableShadowMaps.h"

namespace sb {

class EvsmGL final : public GlTechnique {
public:
    EvsmGL();
    void setScene(const Scene& scene) override;
    /// The light fits and the maps' fit to the receivers follow the scene (FilterableShadowMaps).
    void sceneChanged(const Scene& scene, uint32_t) override { mMaps.fits().sceneChanged(scene); }
    void compile(const CompileContext& ctx) override;
    void execute(FrameContext& ctx) override;
    Counters counters() const override { return mCounters; }
    const MapTexels* mapTexels() const override { return &mMaps.fits(); }

private:
    FilterableShadowMaps mMaps{"evsm"};
    SeparableBlur mBlur;
    const Program* mDepthProgram = nullptr;
    LitPrograms mLighting; ///< the lighting pass (non-receivers apart where they can be)
    Counters mCounters;
};

} // namespace sb
