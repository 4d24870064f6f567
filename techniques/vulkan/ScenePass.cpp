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
                                   VkPipelineLayout layout, std::string& key) {
    GraphicsPipelineDesc d;
    d.vertex = ctx.shaders.get(vertex, defines, GL_VERTEX_SHADER);
    if (!fragment.empty()) d.fragment = ctx.shaders.get(fragment, defines, GL_FRAGMENT_SHADER);
    d.bindings = ctx.submitter.bindings();
    d.attributes = ctx.submitter.attributes();
    d.layout = layout;
    key += vertex + "+" + fragment + "[" + definesKey(defines) + "]";
    return d;
}

} // namespace sb
