#include "techniques/vulkan/LitPipelines.h"

#include "techniques/ReceiverSplit.h"
#include "techniques/vulkan/ScenePass.h"
#include "techniques/vulkan/VulkanTechnique.h"

namespace sb {

namespace {

std::string buildOne(const VulkanCompileContext& ctx, const std::string& vertex, const std::string& fragment,
                     const Defines& defines, VkPipelineLayout layout, const std::string& keyPrefix,
                     ScenePipeline& pipeline) {
    std::string key = keyPrefix;
    const GraphicsPipelineDesc desc = scenePipeline(ctx, vertex, fragment, defines, layout, key);
    pipeline.build(ctx.pipelines, key, desc, ctx.targets);
    return definesKey(defines);
}

} // namespace

std::string LitPipelines::build(const VulkanCompileContext& ctx, const std::string& vertex,
                                const std::string& fragment, const Defines& lit, VkPipelineLayout layout,
                                const std::string& keyPrefix) {
    mSplit = ReceiverSplit::drawsApart(ctx.scene, ctx.submitter.mode());
    if (!mSplit) return buildOne(ctx, vertex, fragment, lit, layout, keyPrefix, mReceivers);
    return buildOne(ctx, vertex, fragment, ReceiverSplit::defines(lit, true), layout, keyPrefix, mReceivers) +
           "|" +
           buildOne(ctx, vertex, fragment, ReceiverSplit::defines(lit, false), layout, keyPrefix,
                    mNonReceivers);
}

void LitPipelines::draw(VulkanFrameContext& ctx, VkPipelineLayout layout, VkDescriptorSet set) const {
    if (!mSplit) {
        drawLitScene(ctx, mReceivers, layout, set);
        return;
    }
    ctx.targets.beginPass(ctx.cmd);
    vkCmdBindPipeline(ctx.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mReceivers.get(ctx.targets));
    ctx.frame.bind(ctx.cmd, layout, ctx.frameOffset);
    if (set != VK_NULL_HANDLE)
        vkCmdBindDescriptorSets(ctx.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 1, 1, &set, 0, nullptr);
    const CullView view = cameraCullView(ctx);
    ctx.submitter.drawCulled(ctx.cmd, layout, DrawSet::Receivers, view, true);
    vkCmdBindPipeline(ctx.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mNonReceivers.get(ctx.targets));
    ctx.submitter.drawCulled(ctx.cmd, layout, DrawSet::NonReceivers, view, true);
    vkCmdEndRenderPass(ctx.cmd);
}

} // namespace sb
