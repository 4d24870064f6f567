#include "techniques/shadowmap/DepthLightingFrame.h"

namespace sb {

SubmitStats DepthLightingFrame::run(FrameContext& ctx, const std::function<void()>& depth,
                                    const std::function<void()>& lighting) {
    ctx.submitter.resetStats();
    ctx.passes.begin("depth");
    depth();
    ctx.passes.begin("lighting");
    lighting();
    return ctx.submitter.stats();
}

} // namespace sb
