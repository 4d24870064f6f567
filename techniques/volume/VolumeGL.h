#pragma once
// `volume`: stencil shadow volumes as in McGuire, "Efficient Shadow Volume Rendering" (GPU Gems
// ch. 9), with each of the chapter's optimisations a property that can be switched off to measure it.
//
// Program structure (Listing 9-1): an ambient pass writes depth and the ambient colour; then per light
// the stencil is cleared, every caster's shadow volume is counted into it with two-sided wrapping
// increment/decrement (colour and depth writes off), and the light's diffuse term is added where the
// count is 0 (depth EQUAL, blend ONE, ONE). The visibility target means shadowing only: 1 in light i's
// channel where that light pass drew, and where it does not run at all (outside the light's scissor
// rectangle or depth bounds, beyond its range: no volume is counted there), 0 where a volume covers.
//
// Volumes (sections 9.2-9.3): light cap (light-facing faces), dark cap (the others sent to infinity
// through w = 0) and sides extruded from silhouette edges, from the CPU per caster and light
// (extrusion=cpu, the chapter's method) or found and extruded in the vertex shader from a mesh with a
// degenerate quad per edge (extrusion=vertex, McGuire and Hughes 2003). The far plane is at infinity
// (Listing 9-2 with an epsilon guard) or replaced by depth clamping (far=depth_clamp); far=finite keeps
// the camera's far plane: a negative control where z-fail loses volumes clipped by it.
//
// Optimisations (properties): mode=auto (z-pass without caps for casters whose volume cannot reach the
// viewport, section 9.5.4; else z-fail), directional (sides as triangles to one point, no dark cap,
// 9.5.1), range_cull (point/spot casters outside the light's range mark nothing, 9.5.2), frustum_cull
// (caps and sides culled separately, 9.5.3), scissor (the light's range rectangle, 9.6.2),
// finite_volumes (extrude by the light's range, 9.6.1), bounded_volumes (past the chapter: directional
// volumes extruded only until they have left the scene's bounds, VolumeGeometry::boundedExtrusion),
// depth_bounds (9.6.3; needs
// GL_EXT_depth_bounds_test, which llvmpipe does not expose: the run is skipped as unsupported there).
//
// The chapter's volumes need closed casters (every edge two faces, after welding). Most model files
// are not closed, so the default open_edges=multiplicity counts every face of an open caster as a
// double-sided occluder with per-edge multiplicities, which is exact for open meshes too (see
// ShadowVolumeMesh.h); the vertex path gets the same volume from a two-sheet extrusion mesh (every
// face and its reversed twin). Closed casters keep the chapter's volumes under either setting (no
// cost for the default). open_edges=refuse names the open mesh and its open edge count instead
// (exit code 2: the scene does not meet what was asked for).
#include <array>
#include <memory>
#include <vector>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "techniques/gl/FrameUniforms.h"
#include "techniques/gl/GlTechnique.h"
#include "techniques/volume/GpuSilhouettesGL.h"
#include "techniques/volume/ShadowVolumeMesh.h"
#include "techniques/volume/SilhouetteInputs.h"
#include "techniques/volume/Volume.h"
#include "techniques/volume/VolumeGeometry.h"
#include "techniques/volume/VolumeMeshBuffers.h"
#include "techniques/volume/VolumePlanner.h"

namespace sb {

class VolumeGL final : public GlTechnique {
public:
    VolumeGL();
    ~VolumeGL() override;
    /// The declaration (name, effects, passes, properties), shared with VolumeVulkan.
    void setScene(const Scene& scene) override;
    void sceneChanged(const Scene& scene, uint32_t changes) override;
    void compile(const CompileContext& ctx) override;
    void execute(FrameContext& ctx) override;
    /// The GPU silhouette paths' volume_triangles is read back from the device here (untimed).
    Counters counters() const override;

    /// The camera projection with its far plane moved to infinity (Listing 9-2 plus the epsilon guard),
    /// from a glm::perspective-style matrix. Public for tests.
    static glm::mat4 infiniteFrom(const glm::mat4& proj) { return VolumePlanner::infiniteFrom(proj); }

private:
    using Draw = VolumePlanner::Draw;
    using FrameStats = VolumePlanner::FrameStats;
    using View = VolumePlanner::View;
    using LightRegion = VolumePlanner::LightRegion;

    /// The ambient pass; the visibility target starts as 1 outside each light's region (no shadow
    /// there), 0 inside (the light pass adds 1 where the stencil count is 0).
    void renderAmbient(FrameContext& ctx, int lights);
    /// Builds the draws of light `i` (CPU silhouettes streamed into one buffer) and counts them.
    void collectDraws(const Light& light, const View& view, FrameStats& stats);
    void markShadows(int light);
    void renderLight(FrameContext& ctx, int light);
    void setStencilCounting(bool zfail) const;
    void readStencilQuery();

    VolumePlanner mPlanner; ///< settings, casters, regions and draw lists (shared with VolumeVulkan)
    const Scene* mScene = nullptr;
    VolumeMeshBuffers mBuffers;
    std::unique_ptr<FrameUniforms> mFrameUniforms; ///< created in compile(): needs a context
    const Program* mAmbientProgram = nullptr;
    const Program* mLightProgram = nullptr;
    const Program* mVolumeProgram = nullptr;
    const Program* mFiniteProgram = nullptr;     ///< finite_volumes: extrusion by the light range
    const Program* mSilhouetteProgram = nullptr; ///< extrusion=compute: shaders/volume/silhouette.comp
    GpuSilhouettesGL mSilhouettes; ///< extrusion=geometry and compute: device count, compute's buffers
    bool mHasDepthBounds = false;

    // Per-frame scratch, kept to avoid allocation in the measured frames.
    std::array<LightRegion, kMaxLights> mRegions{};

    // GL_SAMPLES_PASSED of the marking passes, read one frame late so the frame never waits on it.
    std::array<std::array<GLuint, kMaxLights>, 2> mQueries{};
    std::array<int, 2> mQueriesIssued{}; ///< lights queried in each slot's frame
    uint64_t mQueryFrame = 0;
    double mStencilSamples = 0;
    Counters mCounters;
};

} // namespace sb
