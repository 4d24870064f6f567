#include "techniques/vulkan/VulkanTechnique.h"

#include <algorithm>
#include <vector>

#include "core/Strings.h"

namespace sb {

Defines VulkanCompileContext::defines() const {
    Defines d = submitter.defines();
    addSceneDefines(scene, d);
    return d;
}

std::string VulkanTechnique::checkCapabilities(const VulkanContext& context) const {
    std::vector<std::string> missing, hints;
    for (const Capability& cap : info().capabilitiesOf(Api::Vulkan)) {
        const uint32_t version = context.properties().apiVersion;
        const bool versionOk = VK_API_VERSION_MAJOR(version) > uint32_t(cap.major) ||
                               (VK_API_VERSION_MAJOR(version) == uint32_t(cap.major) &&
                                VK_API_VERSION_MINOR(version) >= uint32_t(cap.minor));
        const bool extensionOk = cap.extension.empty() || context.hasDeviceExtension(cap.extension);
        if (versionOk && extensionOk) continue;
        missing.push_back(cap.name);
        if (!cap.hint.empty() && std::find(hints.begin(), hints.end(), cap.hint) == hints.end())
            hints.push_back(cap.hint);
    }
    if (missing.empty()) return "";
    // Every missing capability in one line, so that a user installs what is needed at once.
    std::string line = name() + " needs " + join(missing, " and ") + " (not available on " +
                       context.info().name + ", Vulkan " + context.info().apiVersion + ")";
    for (const std::string& hint : hints) line += "; " + hint;
    return line;
}

} // namespace sb
