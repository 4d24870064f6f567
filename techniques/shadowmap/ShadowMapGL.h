#pragma once
// `shadowmap`: two-pass shadow mapping (Williams 1978; thesis section 2.4). Pass "depth" renders the
// casters from each light into a layer of a depth texture array, with glPolygonOffset as constant and
// slope-scaled bias; pass "lighting" renders the scene once, comparing each fragment's light-space
// depth with the map (PCF_SIZE^2 taps, hardware compare or shader compare) for every light.
// Filter kernels (property kernel): grid, the pcf x pcf taps one texel apart; poisson, `taps` taps of a
// fixed Poisson disk of `radius` texels (Fernando 2005, Percentage-Closer Soft Shadows, section 3: PCF
// with Poisson-disk taps; techniques/shadowmap/PoissonDisk.h); rotated_grid, an n x n grid (n^2 nearest
// to `taps`) over the square of half-width `radius` rotated per pixel by an angle from interleaved
// gradient noise (Jimenez 2014, Next Generation Post Processing in Call of Duty: Advanced Warfare,
// SIGGRAPH course), which trades the grid's banding for per-pixel noise and is a function of the pixel
// alone, so every submission mode and run gives the same image.
// Biases besides glPolygonOffset: normal_offset moves the lookup position along the surface normal by
// that many world-space texels of the map, times (1 - n.l), so acne goes where the receiver grazes the
// light without pushing contact shadows away where it faces it (Holbert 2010, Normal Offset Shadows;
// Holbert 2011, Saying Goodbye to Shadow Acne, GDC 2011); receiver_plane compares every tap with the
// receiver plane's depth at that tap, from the screen-space derivatives of the shadow coordinate (Isidoro
// 2006, Shadow Mapping: GPU-based Tips and Techniques, GDC 2006, "Receiver Plane Depth Bias";
// shaders/shadowmap/receiver_plane.glsl). Their defaults (grid, 0, false) compile the program these knobs
// did not exist for, so the images are unchanged.
// Directional lights get an orthographic light camera fitted to the casters; spot lights a perspective
// one with the spot cone (scenes/LightFit.h). Each light's depth pass submits only the casters whose
// bounds reach its frustum and, with `cull` (default), whose shadow (swept past the receivers, grown by
// the filter's footprint in world units) may reach the camera's view (scenes/
// InstanceCulling.h; counter casters_culled). Point lights
// need an omni map (`cubemap`, `paraboloid`): refused here with ExitCode::Unsupported.
#include <vector>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "scenes/InstanceCulling.h"
#include "techniques/FlatLightFits.h"
#include "techniques/gl/ContactShadowsGL.h"
#include "techniques/gl/GlTechnique.h"
#include "techniques/gl/LitPrograms.h"
#include "techniques/shadowmap/DepthLayers.h"
#include "techniques/shadowmap/ShadowMap.h"

namespace sb {

class ShadowMapGL final : public GlTechnique {
public:
    ShadowMapGL();
    void propertiesApplied() override; ///< contact=on's pass "view_depth"
    void setScene(const Scene& scene) override;
    /// The light fits, the culling bounds and what depends on the fits (texel sizes, cull margins).
    void sceneChanged(const Scene& scene, uint32_t changes) override;
    void compile(const CompileContext& ctx) override;
    void execute(FrameContext& ctx) override;
    Counters counters() const override { return mCounters; }
    const MapTexels* mapTexels() const override { return &mLights; }

private:
    void renderDepth(FrameContext& ctx);
    /// mTexelWorld and mView's margins from the current fits and properties.
    void fitTexels(const Scene& scene);
    void renderLighting(FrameContext& ctx);

    FlatLightFits mLights;          ///< per light: the camera and the shadow matrix
    DepthLayers mMaps{"shadowmap"}; ///< GL_TEXTURE_2D_ARRAY, layer i = light i
    InstanceCulling mCulling;
    std::vector<uint8_t> mKeep;     ///< the depth pass's mask, reused per light
    size_t mCulled = 0;             ///< casters culled over all lights, last frame
    bool mDrawAllIntoMap = false;   ///< the gate's injected regression "no_caster_culling" only
    std::vector<glm::vec2> mKernel; ///< poisson / rotated_grid tap offsets in texels (empty: grid)
    std::vector<float> mTexelWorld; ///< per light: world size of a texel at w = 1 (normal offset)
    float mNormalOffset = 0.0f;     ///< texels; 0 = off
    bool mCull = true;              ///< leave out casters whose shadow cannot reach the view
    ViewCull mView;                 ///< for mCull: the lights, the receivers, the margins
    const Program* mDepthProgram = nullptr;
    LitPrograms mLighting;     ///< the lighting pass's programs (non-receivers apart where they can be)
    ContactShadowsGL mContact; ///< contact=on: the view depth pre-pass and its binding
    Counters mCounters;
};

} // namespace sb
