#pragma once
// `reference`: exact visibility by ray tracing (Intel Embree), the ground truth every other technique
// is judged against. Pass "gbuffer" renders world positions, object and primitive ids with
// the run's submitter and camera (GBufferRenderer); pass "trace" casts, for every covered pixel and
// every light, occlusion rays (one towards a point light, a stratified set over an area light) on a
// thread pool (ReferenceTracer) and uploads the result as a texture; pass "shade" re-rasterises the
// scene and lights it like `none`, each light's term multiplied by its traced visibility, which is also
// what it writes to the visibility target. The trace runs on the CPU: its time shows up in CPU submit.
#include <memory>
#include <vector>

#include <epoxy/gl.h>

#include "reference/EmbreeScene.h"
#include "reference/GBuffer.h"
#include "reference/GBufferRenderer.h"
#include "reference/Reference.h"
#include "reference/ReferenceTracer.h"
#include "techniques/gl/GlTechnique.h"

namespace sb {

class ReferenceGL final : public GlTechnique {
public:
    ReferenceGL();
    ~ReferenceGL() override;
    void setScene(const Scene& scene) override;
    /// Moving casters rebuild the Embree scene (its acceleration structure: the reference's per-frame
    /// cost of motion); the tracer reads the lights as they are.
    void sceneChanged(const Scene& scene, uint32_t changes) override;
    void compile(const CompileContext& ctx) override;
    void execute(FrameContext& ctx) override;
    /// draw_calls, triangles (G-buffer and shade passes), rays (all lights), rays_per_second_per_thread,
    /// noise_bound (largest over lights), samples_per_pixel (largest over lights).
    Counters counters() const override { return mCounters; }

    /// Per light (up to kMaxLights) of the last frame: the tracer's visibility, -1 off geometry.
    const std::vector<VisibilityImage>& lastVisibility() const { return mVisibility; }
    /// The G-buffer the last frame traced from (the samples of lastVisibility()).
    const GBuffer& lastGBuffer() const { return mGBuffer; }

private:
    void renderGBuffer(FrameContext& ctx);
    void trace();
    void uploadVisibility();
    void shade(FrameContext& ctx);
    void updateCounters(const SubmitStats& shadeStats);
    void ensureTargets(int width, int height);
    void releaseTexture();
    ReferenceTracer::Options tracerOptions() const;

    const Scene* mScene = nullptr;
    std::unique_ptr<EmbreeScene> mEmbree;
    std::unique_ptr<ReferenceTracer> mTracer;
    std::unique_ptr<GBufferRenderer> mGBufferRenderer;
    ProgramCache* mPrograms = nullptr; ///< the harness's cache (the G-buffer program is fetched per frame)
    const Program* mShadeProgram = nullptr;
    GLuint mVisibilityTexture = 0;
    int mWidth = 0, mHeight = 0;
    GBuffer mGBuffer;
    std::vector<VisibilityImage> mVisibility;
    std::vector<TraceStats> mTraceStats;
    Counters mCounters;
};

} // namespace sb
