#include "techniques/none/NoneGL.h"

#include <algorithm>

namespace sb {

NoneGL::NoneGL() : GlTechnique(None::declaration()) {}

void NoneGL::setScene(const Scene&) {}

void NoneGL::compile(const CompileContext& ctx) {
    Defines defines = withLightKinds(ctx.submitter.defines(), ctx.scene);
    defines["LIGHT_COUNT"] = std::to_string(std::clamp<int>(int(ctx.scene.lights.size()), 1, kMaxLights));
    mProgram = &ctx.programs.get({"common/scene.vert", "common/lit.frag", ""}, defines);
    setPermutationKey(mProgram->key());
}

void NoneGL::execute(FrameContext& ctx) {
    ctx.passes.begin("lighting");
    ctx.submitter.resetStats();
    mProgram->use();
    ctx.submitter.drawCulled(DrawSet::All, cameraCullView(ctx));
    const SubmitStats& s = ctx.submitter.stats();
    mCounters = {{"draw_calls", double(s.drawCalls)}, {"triangles", double(s.triangles)}};
}

} // namespace sb
