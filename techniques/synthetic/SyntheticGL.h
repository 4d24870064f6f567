#pragma once
#include "techniques/gl/GlTechnique.h"
#include "techniques/synthetic/Synthetic.h"

namespace sb {

/// `synthetic`: not a shadow technique but a workload whose bottleneck is known by construction, to
/// validate `bench bottleneck` on any GL implementation and to calibrate one's reading of it:
///   fill-bound:   fragment_iterations=N (a full-screen pass with N arithmetic steps per pixel),
///                 draw_scene=false;
///   vertex-bound: the scene's triangles (many, tiny) with a minimal pipeline, vertex_iterations=N;
///   CPU-bound:    many small instances in immediate mode (the draw calls dominate).
/// Visibility is 1 everywhere (no shadows).
class SyntheticGL final : public GlTechnique {
public:
    SyntheticGL();
    ~SyntheticGL() override;
    void setScene(const Scene& scene) override;
    /// The workloads do not depend on where the lights and casters are.
    void sceneChanged(const Scene&, uint32_t) override {}
    void compile(const CompileContext& ctx) override;
    void execute(FrameContext& ctx) override;
    Counters counters() const override { return mCounters; }

private:
    const Program* mScene = nullptr;
    const Program* mFill = nullptr;
    GLuint mEmptyVao = 0; ///< the full-screen triangle needs no buffers, but GL needs a VAO bound
    Counters mCounters;
};

} // namespace sb
