#include "techniques/synthetic/SyntheticVulkan.h"

#include "techniques/synthetic/Synthetic.h"

namespace sb {

SyntheticVulkan::SyntheticVulkan() : VulkanTechnique(Synthetic::declaration()) {}

SyntheticVulkan::~SyntheticVulkan() {
    if (mLayout) vkDestroyPipelineLayout(mDevice, mLayout, nullptr);
}

void SyntheticVulkan::compile(const VulkanCompileContext& ctx) {
    mDevice = ctx.context.device();
    if (!mLayout) mLayout = createScenePipelineLayout(ctx);
    mDrawScene = properties().getBool(Synthetic::kDrawScene);
    mVertexIterations = int(properties().getInt(Synthetic::kVertexIterations));
    mFragmentIterations = int(properties().getInt(Synthetic::kFragmentIterations));
    mDrawFill = mFragmentIterations > 0;
    std::string permutation;
    if (mDrawScene) {
        const Defines defines = ctx.submitter.defines();
        std::string key;
        GraphicsPipelineDesc desc =
            scenePipeline(ctx, "synthetic/scene.vert", "synthetic/scene.frag", defines, mLayout, key);
        mScene.build(ctx.pipelines, key, desc, ctx.targets);
        permutation = "synthetic/scene[" + definesKey(defines) + "]";
    }
    if (mDrawFill) {
        GraphicsPipelineDesc desc;
        const ShaderModules modules =
            ctx.shaders.get(ShaderSources{"common/fullscreen.vert", "synthetic/fill.frag", ""}, {});
        desc.vertex = modules.vertex;
        desc.fragment = modules.fragment;
        desc.layout = mLayout;
        // Over everything, every pixel exactly once: no depth test, no depth writes (as on GL).
        desc.depthTest = false;
        desc.depthWrite = false;
        mFill.build(ctx.pipelines, "common/fullscreen.vert+synthetic/fill.frag|no-depth", desc, ctx.targets);
        permutation += std::string(permutation.empty() ? "" : "|") + "synthetic/fill";
    }
    setPermutationKey(permutation);
}

void SyntheticVulkan::recordScene(VulkanFrameContext& ctx) {
    ctx.targets.beginPass(ctx.cmd);
    vkCmdBindPipeline(ctx.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mScene.get(ctx.targets));
    ctx.frame.bind(ctx.cmd, mLayout, ctx.frameOffset);
    VulkanPush push;
    push.ints.x = mVertexIterations;
    ctx.submitter.drawCulled(ctx.cmd, mLayout, DrawSet::All, cameraCullView(ctx), true, {}, push);
    vkCmdEndRenderPass(ctx.cmd);
}

void SyntheticVulkan::recordFill(VulkanFrameContext& ctx) {
    ctx.targets.beginPass(ctx.cmd);
    vkCmdBindPipeline(ctx.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mFill.get(ctx.targets));
    VulkanPush push;
    push.ints.x = mFragmentIterations;
    push.vec.x = float(ctx.targets.height());
    vkCmdPushConstants(ctx.cmd, mLayout, kPushStages, 0, sizeof push, &push);
    vkCmdDraw(ctx.cmd, 3, 1, 0, 0); // the full-screen triangle (common/fullscreen.vert)
    vkCmdEndRenderPass(ctx.cmd);
}

void SyntheticVulkan::execute(VulkanFrameContext& ctx) {
    ctx.submitter.resetStats();
    ctx.passes.begin("scene");
    if (mDrawScene) recordScene(ctx);
    ctx.passes.begin("fill");
    if (mDrawFill) recordFill(ctx);
    const SubmitStats& s = ctx.submitter.stats();
    mCounters = {{"draw_calls", double(s.drawCalls) + (mDrawFill ? 1.0 : 0.0)},
                 {"triangles", double(s.triangles)}};
}

} // namespace sb
