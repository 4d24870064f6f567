#include "techniques/gl/GlTechnique.h"

namespace sb {

Defines CompileContext::defines() const {
    Defines d = submitter.defines();
    addSceneDefines(scene, d);
    return d;
}

std::string GlTechnique::checkCapabilities(const Context& context) const {
    for (const Capability& cap : info().capabilitiesOf(Api::GL)) {
        const bool versionOk =
            context.glMajor > cap.major || (context.glMajor == cap.major && context.glMinor >= cap.minor);
        const bool extensionOk = cap.extension.empty() || context.hasExtension(cap.extension);
        if (!versionOk || !extensionOk)
            return name() + " needs " + cap.name + " (not available on " + context.renderer + ", GL " +
                   context.version + ")";
    }
    return "";
}

} // namespace sb
