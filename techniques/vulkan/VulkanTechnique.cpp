#include "techniques/vulkan/VulkanTechnique.h"

namespace sb {

Defines VulkanCompileContext::defines() const {
    Defines d = submitter.defines();
    addSceneDefines(scene, d);
    return d;
}

std::string VulkanTechnique::checkCapabilities(const VulkanContext& context) const {
    for (const Capability& cap : info().capabilitiesOf(Api::Vulkan)) {
        const uint32_t version = context.properties().apiVersion;
        const bool versionOk = VK_API_VERSION_MAJOR(version) > uint32_t(cap.major) ||
                               (VK_API_VERSION_MAJOR(version) == uint32_t(cap.major) &&
                                VK_API_VERSION_MINOR(version) >= uint32_t(cap.minor));
        const bool extensionOk = cap.extension.empty() || context.hasDeviceExtension(cap.extension);
        if (!versionOk || !extensionOk)
            return name() + " needs " + cap.name + " (not available on " + context.info().name + ", Vulkan " +
                   context.info().apiVersion + ")";
    }
    return "";
}

} // namespace sb
