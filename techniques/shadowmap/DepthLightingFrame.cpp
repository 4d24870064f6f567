#include "techniques/shadowmap/DepthLightingFrame.h"

#include "techniques/common/ShadowWork.h"

namespace sb {

SubmitStats DepthLightingFrame::run(FrameContext& ctx, const std::function<void()>& depth,
                                    const std::function<void()>& lighting) {
    ctx.submitter.resetStats();
    if (const char* reason = ShadowWork::noneNeeded(ctx.scene)) {
        ctx.passes.skip("depth", reason);
    } else {
        ctx.passes.begin("depth");
        depth();
    }
    ctx.passes.begin("lighting");
    lighting();
    return ctx.submitter.stats();
}

} // namespace sb
