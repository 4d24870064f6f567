#pragma once
// A pipeline layout of descriptor set layouts and at most one push-constant range: what a graphics
// pipeline (vk/GraphicsPipeline.h's createPipelineLayout, whose range is seen by the vertex and
// fragment stages) and a compute pipeline (vk/ComputePipeline.h) are created against, and what a pass
// whose push constants reach other stages (volume's geometry shader) creates with those stages.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

namespace sb {

class VulkanContext;

/// A layout of `sets` and one push-constant range of `pushBytes` bytes seen by `pushStages` (no range
/// when `pushBytes` is 0). Every vkCmdPushConstants into it must pass exactly `pushStages`. Throws
/// sb::Error(Failure) naming the VkResult; the caller owns the layout.
VkPipelineLayout createPipelineLayout(VulkanContext& context, const std::vector<VkDescriptorSetLayout>& sets,
                                      uint32_t pushBytes, VkShaderStageFlags pushStages);

} // namespace sb
