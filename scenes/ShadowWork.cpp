#include "scenes/ShadowWork.h"

#include <algorithm>

namespace sb {

const char* ShadowWork::noneNeeded(const Scene& scene) {
    const auto casts = [](const Light& l) { return l.castsShadows; };
    if (std::none_of(scene.lights.begin(), scene.lights.end(), casts)) return "no light casts shadows";
    const auto receiver = [](const Instance& i) { return i.receivesShadow; };
    if (std::none_of(scene.instances.begin(), scene.instances.end(), receiver))
        return "no instance receives a shadow";
    return nullptr;
}

size_t ShadowWork::unshadowedLights(const Scene& scene, size_t lightCount) {
    const size_t n = std::min(lightCount, scene.lights.size());
    return size_t(std::count_if(scene.lights.begin(), scene.lights.begin() + long(n),
                                [](const Light& l) { return !l.castsShadows; }));
}

} // namespace sb
