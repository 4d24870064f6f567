#pragma once
// Pipelines by key, as gl/ProgramCache keeps programs: a technique compiled again (another run of the
// same configuration, -t auto's candidates, a sweep's points) gets its pipelines back without
// building them again. The key is the technique's: its shader keys (definesKey) and every piece of
// fixed-function state that differs between its pipelines; the cache adds the render-pass variant.
// Owns the pipelines (destroyed with the cache, after every technique that used them).
#include <map>
#include <string>

#include <vulkan/vulkan.h>

#include "vk/GraphicsPipeline.h"

namespace sb {

class VulkanContext;
class VulkanTargets;

class VulkanPipelineCache {
public:
    explicit VulkanPipelineCache(VulkanContext& context) : mContext(context) {}
    ~VulkanPipelineCache();
    VulkanPipelineCache(const VulkanPipelineCache&) = delete;
    VulkanPipelineCache& operator=(const VulkanPipelineCache&) = delete;

    /// The pipeline of `desc` under `key`, built on first use.
    VkPipeline get(const std::string& key, const GraphicsPipelineDesc& desc);
    size_t size() const { return mPipelines.size(); }
    size_t buildCount() const { return mBuilds; }

private:
    VulkanContext& mContext;
    std::map<std::string, VkPipeline> mPipelines;
    size_t mBuilds = 0;
};

/// A scene pass's pipeline in both render-pass variants of the frame targets (with and without the
/// visibility attachment): get() is the one the frame being recorded uses.
class ScenePipeline {
public:
    /// Builds (or finds) both variants of `desc` into `targets`' render passes.
    void build(VulkanPipelineCache& cache, const std::string& key, GraphicsPipelineDesc desc,
               const VulkanTargets& targets);
    VkPipeline get(const VulkanTargets& targets) const;

private:
    VkPipeline mVariant[2]{};
};

} // namespace sb
