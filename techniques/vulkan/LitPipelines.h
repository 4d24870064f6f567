#pragma once
// A lit pass's pipelines on Vulkan: one for the whole scene, or, where techniques/ReceiverSplit.h allows
// it, one for the receivers and one without the shadow lookup for the instances that receive no shadow.
// The Vulkan twin of techniques/gl/LitPrograms.h; both pipelines share one layout, so the technique's
// set stays bound across the switch.
#include <string>

#include <vulkan/vulkan.h>

#include "shading/Defines.h"
#include "techniques/vulkan/VulkanPipelineCache.h"

namespace sb {

struct VulkanCompileContext;
struct VulkanFrameContext;

class LitPipelines {
public:
    /// Builds the pipelines drawing the scene with `vertex` and `fragment` (scenePipeline,
    /// techniques/vulkan/ScenePass.h) for `lit` (the lit pass's defines) and `layout`; `keyPrefix` names
    /// them in the pipeline cache ("pcss-lighting|"). Returns the permutation key of what was built:
    /// definesKey of the one pipeline's defines, or the receivers' and non-receivers' joined by '|'.
    std::string build(const VulkanCompileContext& ctx, const std::string& vertex, const std::string& fragment,
                      const Defines& lit, VkPipelineLayout layout, const std::string& keyPrefix);
    /// Whether the non-receivers are drawn apart with a second pipeline.
    bool split() const { return mSplit; }

    /// drawLitScene's pass (techniques/vulkan/ScenePass.h): begins the targets' render pass, binds the
    /// frame block as set 0 and `set` as set 1, draws DrawSet::All, or the receivers and then the
    /// non-receivers with their pipeline, and ends the pass.
    void draw(VulkanFrameContext& ctx, VkPipelineLayout layout, VkDescriptorSet set) const;

private:
    ScenePipeline mReceivers;
    ScenePipeline mNonReceivers;
    bool mSplit = false;
};

} // namespace sb
