#include "techniques/none/NoneVulkan.h"

#include <algorithm>

#include "shading/ShaderLimits.h"
#include "techniques/none/None.h"
#include "techniques/vulkan/ScenePass.h"

namespace sb {

NoneVulkan::NoneVulkan() : VulkanTechnique(None::declaration()) {}

NoneVulkan::~NoneVulkan() {
    if (mLayout) vkDestroyPipelineLayout(mDevice, mLayout, nullptr);
}

void NoneVulkan::compile(const VulkanCompileContext& ctx) {
    mDevice = ctx.context.device();
    if (!mLayout) mLayout = createScenePipelineLayout(ctx);
    Defines defines = withLightKinds(ctx.submitter.defines(), ctx.scene);
    defines["LIGHT_COUNT"] = std::to_string(std::clamp<int>(int(ctx.scene.lights.size()), 1, kMaxLights));
    std::string key;
    GraphicsPipelineDesc desc =
        scenePipeline(ctx, "common/scene.vert", "common/lit.frag", defines, mLayout, key);
    mPipeline.build(ctx.pipelines, key, desc, ctx.targets);
    setPermutationKey(definesKey(defines));
}

void NoneVulkan::execute(VulkanFrameContext& ctx) {
    ctx.passes.begin("lighting");
    ctx.submitter.resetStats();
    drawLitScene(ctx, mPipeline, mLayout);
    const SubmitStats& s = ctx.submitter.stats();
    mCounters = {{"draw_calls", double(s.drawCalls)}, {"triangles", double(s.triangles)}};
}

} // namespace sb
