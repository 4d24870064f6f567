#pragma once
// Contact shadows (techniques/ContactShadows.h) on a Vulkan member's frame: the wiring every map member
// repeats, in one home (techniques/gl/ContactShadowsGL.h is the GL form). It owns the view depth pre-pass
// (techniques/vulkan/ViewDepthVulkan.h) and, when the member's properties turn `contact` on, adds its set
// to the lighting pipeline's layout (set ViewDepthVulkan::kLightingSet, after the member's own set 1),
// gives the member's frame its first pass and binds the set before the lit draw. With `contact` off it
// creates nothing and adds nothing: the member's pipelines and frame are the ones without it. `cascaded`
// keeps its own ViewDepthVulkan: fit=sdsm reads the same pre-pass (CascadedVulkan.h).
#include <functional>
#include <vector>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "techniques/PropertySet.h"
#include "techniques/vulkan/ViewDepthVulkan.h"

namespace sb {

class ContactShadowsVulkan {
public:
    /// Reads `p` (a member declaring ContactShadows::properties()) and, when on, creates the pre-pass at
    /// the targets' size. Before the lighting pipeline's layout (lightingSets).
    void compile(const PropertySet& p, const VulkanCompileContext& ctx);
    bool enabled() const { return mEnabled; }
    /// The lighting pipeline layout's sets after the frame's set 0: `memberSets` (the member's set 1
    /// only) and, when on, the view depth's set 2.
    std::vector<VkDescriptorSetLayout> lightingSets(std::vector<VkDescriptorSetLayout> memberSets) const;
    /// The first pass of the member's frame (pass ContactShadows::kPass): records the view depth into
    /// ctx.cmd. Empty when off, so that the frame has no such pass.
    std::function<void()> prePass(const VulkanFrameContext& ctx);
    /// Before the lit draw (outside the render pass): writes the block and binds set 2 of `layout` when
    /// on.
    void bind(VkCommandBuffer cmd, VkPipelineLayout layout) const;

private:
    bool mEnabled = false;
    glm::vec4 mBlock{0.0f};
    ViewDepthVulkan mViewDepth;
};

} // namespace sb
