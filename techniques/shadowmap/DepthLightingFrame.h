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
    /// and calls `lighting`; returns the statistics of both.
    static SubmitStats run(FrameContext& ctx, const std::function<void()>& depth,
                           const std::function<void()>& lighting);
};

} // namespace sb
