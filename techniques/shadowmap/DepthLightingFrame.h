#pragma once
// The frame of the two-pass depth-map members (`shadowmap`, `pcss`, `cascaded`, `cubemap`,
// `paraboloid`): the submit statistics reset, pass "depth", pass "lighting", and the statistics their
// counters are made of. One place, so the members' pass names (TechniqueInfo::passes) and their
// draw_calls and triangles count the same work.
#include <functional>

#include "techniques/Technique.h"
#include "techniques/submit/Submitter.h"

namespace sb {

class DepthLightingFrame {
public:
    /// Resets ctx.submitter's statistics, begins pass "depth" and calls `depth`, begins pass "lighting"
    /// and calls `lighting`; returns the statistics of both. Where the scene needs no shadow at all
    /// (ShadowWork::noneNeeded) the depth pass is skipped with that reason and the lighting pass's
    /// program computes none (every light unshadowed or no receiver: common/lighting.glsl).
    static SubmitStats run(FrameContext& ctx, const std::function<void()>& depth,
                           const std::function<void()>& lighting);
};

} // namespace sb
