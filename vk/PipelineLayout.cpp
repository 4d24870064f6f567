#include "vk/PipelineLayout.h"

#include "vk/VulkanContext.h"

namespace sb {

VkPipelineLayout createPipelineLayout(VulkanContext& context, const std::vector<VkDescriptorSetLayout>& sets,
                                      uint32_t pushBytes, VkShaderStageFlags pushStages) {
    const VkPushConstantRange range{pushStages, 0, pushBytes};
    VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    info.setLayoutCount = static_cast<uint32_t>(sets.size());
    info.pSetLayouts = sets.data();
    info.pushConstantRangeCount = pushBytes ? 1 : 0;
    info.pPushConstantRanges = pushBytes ? &range : nullptr;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VulkanContext::check(vkCreatePipelineLayout(context.device(), &info, nullptr, &layout),
                         "vkCreatePipelineLayout");
    return layout;
}

} // namespace sb
