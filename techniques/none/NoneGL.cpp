#include "techniques/none/NoneTechnique.h"

#include <algorithm>

namespace sb {

NoneTechnique::NoneTechnique()
    : Technique({.name = "none",
                 .description = "lit, unshadowed: the baseline of every overhead ratio",
                 .effects = 0,
                 .capabilities = {{"GL 4.5", 4, 5, ""}},
                 .passes = {"lighting"},
                 .properties = {}}) {}

void NoneTechnique::setScene(const Scene&) {}

void NoneTechnique::compile(const CompileContext& ctx) {
    Defines defines = ctx.submitter.defines();
    defines["LIGHT_COUNT"] = std::to_string(std::clamp<int>(int(ctx.scene.lights.size()), 1, kMaxLights));
    mProgram = &ctx.programs.get({"common/scene.vert", "common/lit.frag", ""}, defines);
    setPermutationKey(mProgram->key());
}

void NoneTechnique::execute(FrameContext& ctx) {
    ctx.passes.begin("lighting");
    ctx.submitter.resetStats();
    mProgram->use();
    ctx.submitter.draw(DrawSet::All);
    const SubmitStats& s = ctx.submitter.stats();
    mCounters = {{"draw_calls", double(s.drawCalls)}, {"triangles", double(s.triangles)}};
}

} // namespace sb
