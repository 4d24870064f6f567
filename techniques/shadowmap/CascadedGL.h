#pragma once
// `cascaded`: cascaded shadow maps for directional lights (Engel 2006, Cascaded Shadow Maps, ShaderX5;
// Dimitrov 2007, Cascaded Shadow Maps, NVIDIA whitepaper), with the split positions of the practical
// split scheme (Zhang et al. 2006, Parallel-Split Shadow Maps for Large-scale Virtual Environments,
// section 3; techniques/shadowmap/CascadeSplits.h). `shadowmap` fits one map to the whole scene, so the
// texels near the camera are as large as those far away: near shadows are stair-steps. Here the view
// frustum of each frame (FrameContext view and proj; near and far clipped to the receivers in view) is
// cut into `cascades` slices and each gets its own map fitted to it (techniques/shadowmap/CascadeFit.h:
// the slice's bounding sphere snapped to whole texels when `stabilize`, the tight box when not).
//
// Pass "depth": each cascade's casters (culled against its side and far planes: casters between the
// light and the slice still shadow it, and depth clamping keeps them in the map) into one layer of a
// depth texture array, glPolygonOffset as constant and slope-scaled bias. Cascades whose fits come out
// identical (far slices of an overview, each clamped to the whole casters' bounds) share one map, and
// a cascade no caster reaches is neither cleared nor drawn: the lookup treats it as lit. Pass
// "lighting": each fragment picks its cascade by view depth (the first whose far split lies beyond
// it) and, in the last `blend` fraction of that cascade, blends towards the next one so the change of
// texel size across a split is no seam; PCF pcf x pcf taps one texel apart with hardware compare
// (bilinear), as `shadowmap`. The lighting program is specialised per scene and properties (each
// light's slots, the cascade count, blending on or off are defines), so a spot light runs no cascade
// code and blend=0 no second lookup: on llvmpipe, which executes both sides of every branch, the blend
// band's second lookup is paid by every fragment (city overview: 1.15x shadowmap's frame with blend=0,
// 1.68x with the default 0.1).
//
// fit=sdsm (Lauritzen, Salvi and Lefohn 2011, Sample Distribution Shadow Maps, I3D) adds pass
// "depth_range" before "depth": the view depth pre-pass (techniques/gl/ViewDepthGL.h) reduced on the GPU
// to its min and max depth (techniques/shadowmap/DepthRangeGL.h, read back one frame late), whose
// interval the splits divide logarithmically (CascadeSplits::sampleDistribution).
//
// Spot lights get one perspective map fitted as `shadowmap` does (scenes/LightFit.h); point lights
// need an omni map (`cubemap`, `paraboloid`): refused with ExitCode::Unsupported.
//
// Default resolution 2048 per cascade, as shadowmap's one map: where a cascade is clamped to the
// casters' bounds (the far cascades of an overview) it is then no coarser than shadowmap's map, and
// the near ones are finer. 1024 (4 x 1024^2, shadowmap's texel count) measured 2.4x shadowmap's wrong
// pixels on city's overview, whose cascades all span the whole city.
#include <cstdint>
#include <vector>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "techniques/gl/GlTechnique.h"
#include "techniques/gl/LitPrograms.h"
#include "techniques/gl/ViewDepthGL.h"
#include "techniques/shadowmap/CascadeFit.h"
#include "techniques/shadowmap/Cascaded.h"
#include "techniques/shadowmap/CascadedMaps.h"
#include "techniques/shadowmap/DepthLayers.h"
#include "techniques/shadowmap/DepthRangeGL.h"

namespace sb {

class CascadedGL final : public GlTechnique {
public:
    CascadedGL();
    void propertiesApplied() override; ///< fit=sdsm's pass "depth_range"
    void setScene(const Scene& scene) override;
    void compile(const CompileContext& ctx) override;
    void execute(FrameContext& ctx) override;
    Counters counters() const override { return mCounters; }
    const MapTexels* mapTexels() const override { return &mPlan; }

    /// The split distances (view depth, cascades + 1) and the cascades of directional light `light` of
    /// the last frame: what the tests compare against closed forms.
    const std::vector<float>& splits() const { return mPlan.splits(); }
    const std::vector<Cascade>& cascades(size_t light) const { return mPlan.cascades(light); }
    /// fit=sdsm: the view depth pre-pass and its reduction (for the tests).
    const ViewDepthGL& viewDepth() const { return mViewDepth; }
    const DepthRangeGL& depthRange() const { return mRange; }

private:
    void renderDepth(FrameContext& ctx);
    void renderLighting(FrameContext& ctx);

    CascadedMaps mPlan;            ///< lights, slots, fits and the depth pass's plan (both APIs')
    DepthLayers mMaps{"cascaded"}; ///< GL_TEXTURE_2D_ARRAY, one layer per slot
    ViewDepthGL mViewDepth;        ///< fit=sdsm and contact=on: the view's depth (their first pass)
    DepthRangeGL mRange;           ///< fit=sdsm: its min and max, one frame late
    std::vector<uint8_t> mKeep;    ///< the depth pass's mask, reused per map
    const Program* mDepthProgram = nullptr;
    LitPrograms mLighting; ///< the lighting pass (non-receivers apart where they can be)
    Counters mCounters;
};

} // namespace sb
