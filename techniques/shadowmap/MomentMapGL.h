#pragma once
// The GL form of every filterable shadow map (`vsm`, `esm`, `evsm`, `msm`; techniques/shadowmap/
// MomentMapKind.h says what sets them apart, and each member's declaration header, Vsm.h, Esm.h, Evsm.h
// and Msm.h, its method and measurements). The three passes over FilterableShadowMaps:
//   "depth"    per light the kind's moments of linear light-space depth into an array layer of its
//              format (directional lights an orthographic map, spot lights a perspective one storing
//              distance; casters culled per light frustum; shadowmap/moments.frag);
//   "blur"     a separable Gaussian of `blur` texels over each layer (SeparableBlur; linear, or in log
//              space for esm; 0 = none: the pass exists but does no GL work);
//   "lighting" the kind's fragment shader on the bilinearly filtered moments.
// Point lights need an omni map (`cubemap`, `paraboloid`): refused with ExitCode::Unsupported.
#include "techniques/gl/ContactShadowsGL.h"
#include "techniques/gl/GlTechnique.h"
#include "techniques/gl/LitPrograms.h"
#include "techniques/gl/SeparableBlur.h"
#include "techniques/shadowmap/FilterableShadowMaps.h"
#include "techniques/shadowmap/MomentMapKind.h"

namespace sb {

class MomentMapGL final : public GlTechnique {
public:
    explicit MomentMapGL(const MomentMapKind& kind);
    void setScene(const Scene& scene) override;
    void propertiesApplied() override; ///< contact=on's pass "view_depth"
    /// The light fits and the maps' fit to the receivers follow the scene (FilterableShadowMaps).
    void sceneChanged(const Scene& scene, uint32_t) override { mMaps.fits().sceneChanged(scene); }
    void compile(const CompileContext& ctx) override;
    void execute(FrameContext& ctx) override;
    Counters counters() const override { return mCounters; }
    const MapTexels* mapTexels() const override { return &mMaps.fits(); }
    /// The moments array (one layer per light) after the last frame's blur: for tests.
    GLuint momentsTexture() const { return mMaps.texture(); }
    const FilterableShadowMaps& maps() const { return mMaps; }

private:
    MomentMapKind mKind;
    FilterableShadowMaps mMaps;
    SeparableBlur mBlur;
    const Program* mDepthProgram = nullptr;
    LitPrograms mLighting;     ///< the lighting pass (non-receivers apart where they can be)
    ContactShadowsGL mContact; ///< contact=on: the view depth pre-pass and its binding
    Counters mCounters;
};

} // namespace sb
