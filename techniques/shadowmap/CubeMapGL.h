#pragma once
// `cubemap`: omnidirectional shadow mapping with a depth cube map per point light (Williams 1978,
// Casting curved shadows on curved surfaces: the two-pass depth comparison; Gerasimov 2004,
// Omnidirectional Shadow Mapping, GPU Gems ch. 12: six 90-degree perspective faces at the light,
// looked up by the light-to-fragment direction). Pass "depth" renders the casters into a
// GL_TEXTURE_CUBE_MAP_ARRAY (one cube per point light, 24-bit depth, glPolygonOffset as constant and
// slope-scaled bias); pass "lighting" draws the scene once and compares each fragment's depth in its
// face, computed from the major-axis distance (shaders/shadowmap/cube_lighting.frag), with hardware
// compare and bilinear filtering, PCF n x n on the face.
//
// Property `layered` picks how the six faces are rendered:
//  - true: one pass per light; a geometry shader sends each triangle to the faces whose frustum it
//    may touch (gl_Layer = 6 * cube + face, cube_depth.geom); casters culled against the union of the
//    faces, the range sphere (OmniCulling). Each caster's vertices are transformed once, the geometry
//    stage does the per-face work.
//  - false: six passes per light, each face's casters culled against that face's frustum
//    (scenes/InstanceCulling, CullPlanes::All) and the range sphere: a caster on one side
//    of the light is submitted only to the faces that see it.
// Spot lights keep `shadowmap`'s perspective map and directional lights its orthographic one
// (scenes/LightFit.h), in a separate 2D depth array, so the technique runs on every scene. A point
// light whose range reaches no caster gets no map and no depth work (counter lights_skipped).
//
// Counters: draw_calls, triangles (submitted; the geometry stage's copies are not counted),
// shadow_map_texels (allocated: resolution^2 per face and per flat map), faces_rendered (cube faces
// that were drawn into: six per layered pass, six-pass faces with at least one caster kept),
// casters_culled (per pass: casters not submitted, summed over faces, layered passes and flat maps),
// lights_skipped.
#include <vector>

#include <epoxy/gl.h>

#include "scenes/InstanceCulling.h"
#include "techniques/gl/ContactShadowsGL.h"
#include "techniques/gl/GlTechnique.h"
#include "techniques/gl/LitPrograms.h"
#include "techniques/shadowmap/CubeFaces.h"
#include "techniques/shadowmap/CubeMap.h"
#include "techniques/shadowmap/DepthLayers.h"
#include "techniques/shadowmap/OmniCulling.h"
#include "techniques/shadowmap/OmniLightSet.h"

namespace sb {

class CubeMapGL final : public GlTechnique {
public:
    CubeMapGL();
    /// The declaration (name, effects, passes, properties, quality knobs), shared with the Vulkan form
    /// (CubeMapVulkan.h).
    void setScene(const Scene& scene) override;
    void propertiesApplied() override; ///< contact=on's pass "view_depth"
    void compile(const CompileContext& ctx) override;
    void execute(FrameContext& ctx) override;
    Counters counters() const override { return mCounters; }
    const MapTexels* mapTexels() const override { return &mLights; }

    /// Whether a context can render the faces in one layered pass (a geometry shader writing gl_Layer
    /// of a cube map array with 18 output vertices): GL 3.2 and up.
    static bool layeredAvailable(const Context& context);

private:
    ContactShadowsGL mContact; ///< contact=on: the view depth pre-pass and its binding
    void renderDepth(FrameContext& ctx);
    void renderCubesLayered(FrameContext& ctx);
    void renderCubesSixPass(FrameContext& ctx);
    void renderLighting(FrameContext& ctx);

    OmniLightSet mLights;
    std::vector<CubeMap::Cube> mCubeLights; ///< per point light with a map, in cube order
    InstanceCulling mCulling;
    OmniCulling mOmniCulling;
    DepthLayers mCubes; ///< GL_TEXTURE_CUBE_MAP_ARRAY, layer-face 6 * cube + face
    DepthLayers mFlat;  ///< GL_TEXTURE_2D_ARRAY: spot and directional maps
    std::vector<uint8_t> mKeep, mRange;
    bool mLayered = true; ///< what compile() chose (the property, where the context allows it)
    size_t mCulled = 0;
    int mFacesRendered = 0;
    const Program* mFaceDepth = nullptr;    ///< flat maps and six-pass faces: common/depth.vert
    const Program* mLayeredDepth = nullptr; ///< cube_depth.vert + cube_depth.geom
    LitPrograms mLighting;                  ///< the lighting pass (non-receivers apart where they can be)
    Counters mCounters;
};

} // namespace sb
