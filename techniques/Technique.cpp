#include "techniques/Technique.h"

namespace sb {

Defines CompileContext::defines() const {
    Defines d = submitter.defines();
    if (scene.hasNonReceivers()) d["SB_NON_RECEIVERS"] = "";
    if (const uint32_t mask = scene.shadowlessLightMask())
        d["SB_SHADOWLESS_LIGHTS"] = std::to_string(mask) + "u";
    return d;
}

Technique::Technique(TechniqueInfo info)
    : mInfo(std::move(info)), mProperties(mInfo.name, mInfo.properties) {}

void Technique::sceneChanged(const Scene& scene, uint32_t) {
    setScene(scene);
}

std::string Technique::checkCapabilities(const Context& context) const {
    for (const Capability& cap : mInfo.capabilities) {
        bool versionOk = context.glMajor > cap.glMajor ||
                         (context.glMajor == cap.glMajor && context.glMinor >= cap.glMinor);
        bool extensionOk = cap.extension.empty() || context.hasExtension(cap.extension);
        if (!versionOk || !extensionOk)
            return mInfo.name + " needs " + cap.name + " (not available on " + context.renderer + ", GL " +
                   context.version + ")";
    }
    return "";
}

} // namespace sb
