#include "techniques/vulkan/ScenePass.h"

#include "techniques/vulkan/VulkanTechnique.h"

namespace sb {

VkPipelineLayout createScenePipelineLayout(const VulkanCompileContext& ctx,
                                           const std::vector<VkDescriptorSetLayout>& sets) {
    std::vector<VkDescriptorSetLayout> all{ctx.frame.setLayout()};
    all.insert(all.end(), sets.begin(), sets.end());
    return createPipelineLayout(ctx.context, all, sizeof(VulkanPush));
}

GraphicsPipelineDesc scenePipeline(const VulkanCompileContext& ctx, const std::string& vertex,
                                   const std::string& fragment, const Defines& defines,
                                   VkPipelineLayout layout, std::string& key, const std::string& geometry) {
    GraphicsPipelineDesc d;
    const ShaderModules modules = ctx.shaders.get(ShaderSources{vertex, fragment, geometry}, defines);
    d.vertex = modules.vertex;
    d.geometry = modules.geometry;
    d.fragment = modules.fragment;
    d.bindings = ctx.submitter.bindings();
    d.attributes = ctx.submitter.attributes();
    d.layout = layout;
    // The submitter sets cull mode and front face per pass and instance (VulkanSubmitter::setCullView).
    d.dynamicCull = ctx.submitter.dynamicCull();
    key += d.dynamicCull ? "cull-dynamic+" : "";
    key +=
        vertex + "+" + fragment + "[" + definesKey(defines) + "]" + (geometry.empty() ? "" : "+" + geometry);
    return d;
}

CullView cameraCullView(const VulkanFrameContext& ctx) {
    return {ctx.proj * ctx.view, false};
}

void drawLitScene(VulkanFrameContext& ctx, const ScenePipeline& pipeline, VkPipelineLayout layout,
                  VkDescriptorSet set) {
    ctx.targets.beginPass(ctx.cmd);
    vkCmdBindPipeline(ctx.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.get(ctx.targets));
    ctx.frame.bind(ctx.cmd, layout, ctx.frameOffset);
    if (set != VK_NULL_HANDLE)
        vkCmdBindDescriptorSets(ctx.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 1, 1, &set, 0, nullptr);
    ctx.submitter.drawCulled(ctx.cmd, layout, DrawSet::All, cameraCullView(ctx), true);
    vkCmdEndRenderPass(ctx.cmd);
}

} // namespace sb
