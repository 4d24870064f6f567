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
// Known limit (the paper's own): the projection is non-linear, but it is applied per vertex and the
// rasteriser joins the projected vertices by straight lines and interpolates their depths linearly.
// Two errors follow, both growing with a triangle's angular size seen from the light:
//  - a straight caster edge should map to a curve; drawn as its chord, the edge and its shadow move
//    by the curve's sagitta (worst near the rim, d.z near 0): the shadow of a coarse square bows in;
//  - the distance to the light is not linear across a triangle: a flat face's middle is nearer
//    than its vertices, the interpolated depth is too far, and light leaks through the middle of a
//    large face (the shadow of a 5 x 5 slab made of one quad a face, 1.5 below the light, has a lit
//    hole under the light: tests/OmniShadowGLTest, ParaboloidKnownLimit).
// Finely tessellated casters are right (the same slab cut into 32 x 32 quads a face has no error off
// the edge band), coarse ones are not: tessellation matters. The cube map's faces are perspective
// projections, under which lines stay lines and depth interpolates exactly, so `cubemap` has neither.
//
// Spot and directional lights keep `shadowmap`'s perspective and orthographic maps (scenes/LightFit.h),
// in further layers of the same array. A point light whose range reaches no caster gets no map and no
// depth work (counter lights_skipped). Counters: draw_calls, triangles, shadow_map_texels (allocated),
// hemispheres_rendered (halves drawn into: at least one caster kept), casters_culled (per pass:
// casters not submitted, summed over hemispheres and flat maps), lights_skipped.
#include <vector>

#include <epoxy/gl.h>

#include "scenes/InstanceCulling.h"
#include "techniques/gl/GlTechnique.h"
#include "techniques/shadowmap/DepthLayers.h"
#include "techniques/shadowmap/OmniCulling.h"
#include "techniques/shadowmap/OmniLightSet.h"
#include "techniques/shadowmap/Paraboloid.h"

namespace sb {

class ParaboloidGL final : public GlTechnique {
public:
    ParaboloidGL();
    void setScene(const Scene& scene) override;
    void compile(const CompileContext& ctx) override;
    void execute(FrameContext& ctx) override;
    Counters counters() const override { return mCounters; }

    /// The axis of hemisphere `half` (0 front: -Y, 1 back: +Y), as shaders/shadowmap/paraboloid_frame.glsl
    /// sets it up.
    static glm::vec3 hemisphereAxis(int half);

private:
    void renderDepth(FrameContext& ctx);
    void renderHemispheres(FrameContext& ctx);
    void renderLighting(FrameContext& ctx);
    int flatBase() const { return 2 * mLights.omniCount(); } ///< first layer of the flat maps

    OmniLightSet mLights;
    InstanceCulling mCulling;
    OmniCulling mOmniCulling;
    DepthLayers mMaps; ///< GL_TEXTURE_2D_ARRAY: 2 * light + half, then the flat maps
    std::vector<uint8_t> mKeep;
    size_t mCulled = 0;
    int mHemispheresRendered = 0;
    const Program* mFlatDepth = nullptr;       ///< shadowmap/depth.vert
    const Program* mParaboloidDepth = nullptr; ///< paraboloid_depth.vert
    const Program* mLighting = nullptr;
    Counters mCounters;
};

} // namespace sb
