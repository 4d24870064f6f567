#include "techniques/Technique.h"

namespace sb {

Technique::Technique(TechniqueInfo info)
    : mInfo(std::move(info)), mProperties(mInfo.name, mInfo.properties) {}

void Technique::sceneChanged(const Scene& scene, uint32_t) {
    setScene(scene);
}

void addShadowExceptionDefines(const Scene& scene, Defines& defines) {
    if (scene.hasNonReceivers()) defines["SB_NON_RECEIVERS"] = "";
    if (const uint32_t mask = scene.shadowlessLightMask())
        defines["SB_SHADOWLESS_LIGHTS"] = std::to_string(mask) + "u";
}

} // namespace sb
