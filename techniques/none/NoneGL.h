#pragma once
// `none`, the smallest technique and the template for a new one (docs/ARCHITECTURE.md, "Extending"):
// one pass through the shared shaders, no properties, the counters every technique reports.
#include "techniques/gl/GlTechnique.h"
#include "techniques/none/None.h"

namespace sb {

/// `none`: lit, unshadowed, one pass. The baseline every overhead ratio is taken against; visibility
/// is 1 everywhere.
class NoneGL final : public GlTechnique {
public:
    NoneGL();
    void setScene(const Scene& scene) override;
    /// Nothing depends on where the lights and casters are.
    void sceneChanged(const Scene&, uint32_t) override {}
    void compile(const CompileContext& ctx) override;
    void execute(FrameContext& ctx) override;
    Counters counters() const override { return mCounters; }

private:
    const Program* mProgram = nullptr;
    Counters mCounters;
};

} // namespace sb
