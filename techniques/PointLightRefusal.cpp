#include "techniques/PointLightRefusal.h"

#include <algorithm>

#include "core/Error.h"
#include "shading/ShaderLimits.h"

namespace sb {

const std::vector<std::string>& PointLightRefusal::omniTechniques() {
    static const std::vector<std::string> kOmni = {"cubemap", "paraboloid"};
    return kOmni;
}

std::vector<std::string> PointLightRefusal::omniHybrids() {
    std::vector<std::string> out;
    for (const std::string& t : omniTechniques()) out.push_back("hybrid:cast=" + t);
    return out;
}

std::string PointLightRefusal::message(const std::string& technique, size_t index) {
    std::vector<std::string> alternatives = omniTechniques();
    for (std::string& h : omniHybrids()) alternatives.push_back(std::move(h));
    std::string use;
    for (size_t k = 0; k < alternatives.size(); ++k)
        use += (k == 0                         ? ""
                : k + 1 == alternatives.size() ? " or "
                                               : ", ") +
               std::string("-t ") + alternatives[k];
    return technique + ": light " + std::to_string(index) +
           " is a point light, which needs an omni shadow map: use " + use +
           ", or --light directional or --light spot";
}

void PointLightRefusal::refuse(const Light& light, size_t index, const std::string& technique) {
    if (light.type == LightType::Point) throw Error(message(technique, index), ExitCode::Unsupported);
}

bool PointLightRefusal::sceneHasOne(const Scene& scene) {
    const size_t count = std::min<size_t>(scene.lights.size(), kMaxLights);
    return std::any_of(scene.lights.begin(), scene.lights.begin() + long(count),
                       [](const Light& l) { return l.type == LightType::Point && l.castsShadows; });
}

} // namespace sb
