#include "techniques/TechniqueInfo.h"

namespace sb {

const char* apiName(Api api) {
    return api == Api::Vulkan ? "vulkan" : "gl";
}

std::optional<Api> parseApi(const std::string& name) {
    if (name == "gl") return Api::GL;
    if (name == "vulkan") return Api::Vulkan;
    return std::nullopt;
}

std::vector<Capability> TechniqueInfo::capabilitiesOf(Api api) const {
    std::vector<Capability> out;
    for (const Capability& c : capabilities)
        if (c.api == api) out.push_back(c);
    return out;
}

} // namespace sb
