#pragma once
// `paraboloid`: dual-paraboloid shadow maps for point lights (Brabec, Annen, Seidel 2002, Shadow
// Mapping for Hemispherical and Omnidirectional Light Sources; Williams 1978 for the depth
// comparison). Each point light gets two hemispherical maps, front (around -Y, the scene below the
// light) and back (+Y), as two layers of a 2D depth array: pass "depth" maps each caster vertex with
// the paraboloid projection (d.x, d.y) / (1 + d.z) of its direction from the light in the hemisphere's
// frame and writes its distance to the light, linear between near and far, as depth
// (shaders/shadowmap/paraboloid_depth.vert); the part of a triangle behind the hemisphere's plane is
// clipped (gl_ClipDistance). Pass "lighting" picks the hemisphere by the sign of the light-to-fragment
// vector along the axis and compares the fragment's distance with the map (hardware compare, bilinear,
// PCF n x n in map space). Two passes per light instead of the cube's six; casters are culled per
// hemisphere: one wholly behind its plane, or wholly outside the range sphere, is not drawn into it.
//
// The paper's limit, and what is done about it: the projection is non-linear, but applied per vertex
// the rasteriser joins the projected vertices by straight lines and interpolates their depths
// linearly. Three errors follow, all growing with a triangle's angular size seen from the light:
//  - a straight caster edge should map to a circular arc; drawn as its chord, the edge and its shadow
//    move by the arc's sagitta (worst near the rim, d.z near 0): the shadow of a coarse square bows in;
//  - a triangle crossing the halves' plane is clipped there along a chord of the rim instead of the
//    rim itself, so a band about the light's height is in neither half: the wall shadow of a pillar
//    that spans the plane loses a band across its whole width (scenes/data/room.json: 7.79% of the
//    'wall' view wrong, the cube 0.005%);
//  - the distance to the light is not linear across a triangle: a flat face's middle is nearer
//    than its vertices, the interpolated depth is too far, and light leaks through the middle of a
//    large face (tests/OmniShadowGLTest, ParaboloidKnownLimit, with split=false).
// So with `split` (the default) each hemisphere's casters are sorted on the CPU
// (ParaboloidSplitting): those whose every edge spans at most sqrt(8 / resolution) rad seen from the
// light (a chord within half a texel of its arc) go through the per-vertex stage as the paper draws
// them; the others through a geometry stage (shaders/shadowmap/paraboloid_split.geom) that cuts each
// triangle into n x n (n <= 13) and projects every grid vertex. Edges wider than 13 segments' worth
// (46 degrees at 2048^2) are cut into 13 and keep a sagitta of (angle / 13)^2 * resolution / 16 texels.
// The cube map's faces are perspective projections, under which lines stay lines and depth
// interpolates exactly, so `cubemap` has none of this.
//
// Spot and directional lights keep `shadowmap`'s perspective and orthographic maps (scenes/LightFit.h),
// in further layers of the same array. A point light whose range reaches no caster gets no map and no
// depth work (counter lights_skipped). Counters: draw_calls, triangles, shadow_map_texels (allocated),
// hemispheres_rendered (halves drawn into: at least one caster kept), casters_culled (per pass:
// casters not submitted, summed over hemispheres and flat maps), casters_split (casters drawn through
// the splitting stage, summed over hemispheres), lights_skipped.
#include <vector>

#include <epoxy/gl.h>

#include "scenes/InstanceCulling.h"
#include "techniques/gl/ContactShadowsGL.h"
#include "techniques/gl/GlTechnique.h"
#include "techniques/gl/LitPrograms.h"
#include "techniques/shadowmap/DepthLayers.h"
#include "techniques/shadowmap/OmniCulling.h"
#include "techniques/shadowmap/OmniLightSet.h"
#include "techniques/shadowmap/Paraboloid.h"
#include "techniques/shadowmap/ParaboloidSplitting.h"

namespace sb {

class ParaboloidGL final : public GlTechnique {
public:
    ParaboloidGL();
    void setScene(const Scene& scene) override;
    void propertiesApplied() override; ///< contact=on's pass "view_depth"
    void compile(const CompileContext& ctx) override;
    void execute(FrameContext& ctx) override;
    Counters counters() const override { return mCounters; }
    const MapTexels* mapTexels() const override { return &mLights; }

private:
    ContactShadowsGL mContact; ///< contact=on: the view depth pre-pass and its binding
    void renderDepth(FrameContext& ctx);
    void renderHemispheres(FrameContext& ctx);
    /// Draws mKeep's casters into the bound half: through the splitting geometry stage those whose
    /// edges are too wide for the per-vertex projection, the rest per vertex.
    void drawHemisphere(FrameContext& ctx, const glm::vec4& light);
    void renderLighting(FrameContext& ctx);
    int flatBase() const { return 2 * mLights.omniCount(); } ///< first layer of the flat maps

    OmniLightSet mLights;
    InstanceCulling mCulling;
    OmniCulling mOmniCulling;
    ParaboloidSplitting mSplitting;
    DepthLayers mMaps; ///< GL_TEXTURE_2D_ARRAY: 2 * light + half, then the flat maps
    std::vector<uint8_t> mKeep, mKeepPlain, mKeepSplit;
    size_t mCulled = 0;
    size_t mSplitDrawn = 0;
    float mMaxSegmentAngle = 0.0f;
    float mBeyondRim = 0.0f;
    int mHemispheresRendered = 0;
    const Program* mFlatDepth = nullptr;       ///< common/depth.vert
    const Program* mParaboloidDepth = nullptr; ///< paraboloid_depth.vert
    const Program* mSplitDepth = nullptr;      ///< cube_depth.vert + paraboloid_split.geom
    bool mSplit = true;                        ///< property split: route wide casters through mSplitDepth
    LitPrograms mLighting;                     ///< the lighting pass (non-receivers apart where they can be)
    Counters mCounters;
};

} // namespace sb
