#include "techniques/vulkan/VulkanTechnique.h"

namespace sb {

Defines VulkanCompileContext::defines() const {
    Defines d = submitter.defines();
    if (scene.hasNonReceivers()) d["SB_NON_RECEIVERS"] = "";
    if (const uint32_t mask = scene.shadowlessLightMask())
        d["SB_SHADOWLESS_LIGHTS"] = std::to_string(mask) + "u";
    return d;
}

VulkanTechnique::VulkanTechnique(TechniqueInfo info)
    : mInfo(std::move(info)), mProperties(mInfo.name, mInfo.properties) {
    // GL capabilities say nothing about a Vulkan device; what a Vulkan technique needs it checks in
    // compile() against the device's features.
    mInfo.capabilities.clear();
}

void VulkanTechnique::sceneChanged(const Scene& scene, uint32_t) {
    setScene(scene);
}

} // namespace sb
