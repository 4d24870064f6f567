#pragma once
// The frame of the two-pass depth-map techniques (the shadow-map family's `shadowmap`, `pcss`,
// `cascaded`, `cubemap`, `paraboloid`, and `virtual`), on both APIs: the submit statistics reset, pass
// "depth", pass "lighting", and the counters made of their statistics. One place, so every member's pass names (TechniqueInfo::passes) and
// its draw_calls and triangles count the same work on GL and on Vulkan.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "scenes/ShadowWork.h"
#include "techniques/Submission.h"
#include "techniques/TechniqueInfo.h"

namespace sb {

class DepthLightingFrame {
public:
    /// Resets ctx.submitter's statistics, begins pass "depth" and calls `depth`, begins pass "lighting"
    /// and calls `lighting`; returns the statistics of both. Where the scene needs no shadow at all
    /// (ShadowWork::noneNeeded) the depth pass is skipped with that reason and the lighting pass's
    /// program computes none (every light unshadowed or no receiver: common/lighting.glsl). `FrameCtx` is
    /// either API's frame context (techniques/gl/GlTechnique.h, techniques/vulkan/VulkanTechnique.h):
    /// both have the scene, a submitter with resetStats()/stats() and a pass timer with begin()/skip().
    /// `first`, where given, runs first in pass `firstPass` (skipped with the depth pass): the view depth
    /// pre-pass of `cascaded` fit=sdsm with its reduction ("depth_range") or of contact shadows
    /// ("view_depth", techniques/ContactShadows.h).
    template <typename FrameCtx>
    static SubmitStats run(FrameCtx& ctx, const std::function<void()>& depth,
                           const std::function<void()>& lighting, const std::function<void()>& first = {},
                           const char* firstPass = "depth_range") {
        ctx.submitter.resetStats();
        if (const char* reason = ShadowWork::noneNeeded(ctx.scene)) {
            if (first) ctx.passes.skip(firstPass, reason);
            ctx.passes.skip("depth", reason);
        } else {
            if (first) {
                ctx.passes.begin(firstPass);
                first();
            }
            ctx.passes.begin("depth");
            depth();
        }
        ctx.passes.begin("lighting");
        lighting();
        return ctx.submitter.stats();
    }

    /// The counters every member reports, in this order: draw_calls and triangles of the frame (`s`),
    /// shadow_map_texels (all maps' texels), then the member's own (`extra`, in its order).
    static Counters counters(const SubmitStats& s, double mapTexels,
                             std::vector<std::pair<std::string, double>> extra) {
        Counters out = {{"draw_calls", double(s.drawCalls)},
                        {"triangles", double(s.triangles)},
                        {"shadow_map_texels", mapTexels}};
        for (auto& e : extra) out.push_back(std::move(e));
        return out;
    }
};

} // namespace sb
