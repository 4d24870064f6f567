#include "techniques/vulkan/VulkanPipelineCache.h"

#include "vk/VulkanContext.h"
#include "vk/VulkanTargets.h"

namespace sb {

VulkanPipelineCache::~VulkanPipelineCache() {
    for (auto& [key, pipeline] : mPipelines) vkDestroyPipeline(mContext.device(), pipeline, nullptr);
}

VkPipeline VulkanPipelineCache::get(const std::string& key, const GraphicsPipelineDesc& desc) {
    auto it = mPipelines.find(key);
    if (it != mPipelines.end()) return it->second;
    ++mBuilds;
    return mPipelines[key] = createGraphicsPipeline(mContext, desc);
}

void ScenePipeline::build(VulkanPipelineCache& cache, const std::string& key, GraphicsPipelineDesc desc,
                          const VulkanTargets& targets) {
    for (int v = 0; v < 2; ++v) {
        desc.renderPass = targets.renderPass(v == 1);
        desc.colourAttachments = targets.colourAttachments(v == 1);
        mVariant[v] = cache.get(key + (v ? "|visibility" : "|colour"), desc);
    }
}

VkPipeline ScenePipeline::get(const VulkanTargets& targets) const {
    return mVariant[targets.visibilityOutput() ? 1 : 0];
}

} // namespace sb
