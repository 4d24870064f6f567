#pragma once
// `pcss`: Percentage-Closer Soft Shadows (Fernando 2005, Percentage-Closer Soft Shadows, SIGGRAPH 2005
// sketch; the NVIDIA whitepaper of the same name, its three steps). Pass "depth" renders the casters from
// each light into a layer of a depth texture array, as `shadowmap` does (glPolygonOffset bias, casters
// culled against the light's frustum: scenes/InstanceCulling.h, counter casters_culled). Pass
// "lighting" shades the scene once; per light and fragment (shaders/shadowmap/pcss.frag):
//   1. blocker search: `blocker_taps` Poisson-disk taps (techniques/shadowmap/PoissonDisk.h) over the
//      region of the map where casters between the receiver and the light can lie: the light's extent
//      seen from the receiver through the map's near plane, w_search = L (d_r - d_near) / d_near
//      (Fernando 2005, section 3, step 1); depths read through a sampler without comparison; the
//      average of the depths in front of the receiver is the blocker depth d_b. d_near is the nearest
//      caster's depth (the casters' bounds seen from the light), which is what the near plane stands
//      for: a directional light's orthographic map reaches from the whole scene's bounds (the ground
//      included), and its near plane would widen the search several times over, finding casters that
//      cannot shadow the receiver;
//   2. penumbra estimate by similar triangles, w = L (d_r - d_b) / d_b (Fernando 2005, equation 1;
//      the blocker and the receiver taken parallel to the light);
//   3. PCF over that width: `filter_taps` Poisson-disk taps through a comparison sampler (bilinear
//      hardware compare), each tap compared with the receiver plane's depth at the tap (Isidoro 2006,
//      receiver-plane depth bias, shaders/shadowmap/receiver_plane.glsl) so the wide kernels do not
//      shadow a sloped receiver itself.
// The one depth texture is bound twice, to units 0 and 1, with two sampler objects: nearest without
// comparison for the search, linear with comparison for the filter, both clamped to a border of depth 1
// (no caster outside the map). A directional light's map is fitted to the casters, but their penumbrae
// reach past it, so receivers outside the map search too unless their search region misses it.
// Depth is linearised per light: spot lights get a perspective map (depth linearised from the map's
// near and far planes, L the emitter's diameter in world units); directional lights an orthographic map
// (linear depth), where the light subtends a fixed angle, so its size at depth d is L d with L = 2 tan of
// the angular radius: w = L (d_r - d_b) and w_search = L (d_r - d_near), in world units perpendicular to
// the light. L comes from the scene's emitter (scenes/Scene.h: a spot light's disk or sphere diameter, or
// for a rect the diameter of the disk of the same area; a directional disk's angular radius) unless
// `light_size` overrides it; a light with no extent
// (shape point, or size 0) gets a 1 degree emitter (L = 2 tan 0.5 deg, times the distance to the casters'
// centre for a spot light), counted in light_size_defaulted. Point lights need an omni map (`cubemap`,
// `paraboloid`): refused with ExitCode::Unsupported.
#include <vector>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "scenes/InstanceCulling.h"
#include "techniques/FlatLightFits.h"
#include "techniques/gl/ContactShadowsGL.h"
#include "techniques/gl/GlTechnique.h"
#include "techniques/gl/LitPrograms.h"
#include "techniques/shadowmap/DepthLayers.h"
#include "techniques/shadowmap/Pcss.h"

namespace sb {

class PcssGL final : public GlTechnique {
public:
    PcssGL();
    ~PcssGL() override;
    void setScene(const Scene& scene) override;
    void propertiesApplied() override; ///< contact=on's pass "view_depth"
    /// The light fits, the culling bounds and each light's size in map texels follow the scene.
    void sceneChanged(const Scene& scene, uint32_t changes) override;
    void compile(const CompileContext& ctx) override;
    void execute(FrameContext& ctx) override;
    Counters counters() const override { return mCounters; }
    const MapTexels* mapTexels() const override { return &mLights; }

    /// Per light: Pcss::LightParams (techniques/shadowmap/Pcss.h), shared with the Vulkan form.
    using LightParams = Pcss::LightParams;

private:
    ContactShadowsGL mContact;              ///< contact=on: the view depth pre-pass and its binding
    void fitLightSizes(const Scene& scene); ///< mParams for the current fits and light_size
    void renderDepth(FrameContext& ctx);
    void renderLighting(FrameContext& ctx);
    void createSamplers();
    void uploadLightUniforms() const;

    FlatLightFits mLights;            ///< per light: the camera and the shadow matrix
    std::vector<LightParams> mParams; ///< per light, for the current light_size
    DepthLayers mMaps{"pcss"};        ///< GL_TEXTURE_2D_ARRAY, layer i = light i
    GLuint mSearchSampler = 0;        ///< nearest, no comparison: raw depths for the blocker search
    GLuint mCompareSampler = 0;       ///< linear, GL_LEQUAL comparison: the filter's taps
    std::vector<glm::vec2> mBlockerKernel, mFilterKernel; ///< unit-disk Poisson taps
    InstanceCulling mCulling;
    std::vector<uint8_t> mKeep; ///< the depth pass's mask, reused per light
    size_t mCulled = 0;         ///< casters culled over all lights, last frame
    const Program* mDepthProgram = nullptr;
    LitPrograms mLighting; ///< the lighting pass (non-receivers apart where they can be)
    Counters mCounters;
};

} // namespace sb
