#include "techniques/vulkan/ContactShadowsVulkan.h"

#include <string>

#include "core/Error.h"
#include "techniques/ContactShadows.h"
#include "techniques/vulkan/VulkanTechnique.h"

namespace sb {

void ContactShadowsVulkan::compile(const PropertySet& p, const VulkanCompileContext& ctx) {
    mEnabled = ContactShadows::enabled(p);
    mBlock = ContactShadows::block(p);
    if (mEnabled) mViewDepth.compile(ctx);
}

std::vector<VkDescriptorSetLayout>
ContactShadowsVulkan::lightingSets(std::vector<VkDescriptorSetLayout> memberSets) const {
    if (!mEnabled) return memberSets;
    // contact_shadow.glsl reads set 2: the frame's set 0 and the member's one set 1 come before it.
    if (memberSets.size() + 1 != ViewDepthVulkan::kLightingSet)
        throw Error("contact shadows: the lighting pipeline has " + std::to_string(memberSets.size()) +
                    " member sets; the view depth's set must be set " +
                    std::to_string(ViewDepthVulkan::kLightingSet));
    memberSets.push_back(mViewDepth.lightingSetLayout());
    return memberSets;
}

std::function<void()> ContactShadowsVulkan::prePass(const VulkanFrameContext& ctx) {
    if (!mEnabled) return {};
    return [this, &ctx] { mViewDepth.record(ctx, ctx.cmd); };
}

void ContactShadowsVulkan::bind(VkCommandBuffer cmd, VkPipelineLayout layout) const {
    if (mEnabled) mViewDepth.bindForLighting(cmd, layout, mBlock);
}

} // namespace sb
