#include "techniques/Technique.h"

#include <algorithm>
#include <string>

#include "shading/ShaderLimits.h"

namespace sb {

Technique::Technique(TechniqueInfo info)
    : mInfo(std::move(info)), mProperties(mInfo.name, mInfo.properties) {}

void Technique::sceneChanged(const Scene& scene, uint32_t) {
    setScene(scene);
}

namespace {

/// One bit per light of `scene` (at most kMaxLights) for which `has` is true, as a GLSL uint literal.
template <typename Predicate>
std::string lightMask(const Scene& scene, Predicate has) {
    uint32_t mask = 0;
    for (size_t i = 0; i < scene.lights.size() && i < size_t(kMaxLights); ++i)
        if (has(scene.lights[i])) mask |= 1u << i;
    return std::to_string(mask) + "u";
}

} // namespace

void addLightKindDefines(const Scene& scene, Defines& defines) {
    defines["SB_STATIC_LIGHTS"] = "";
    defines["SB_POSITIONAL_LIGHTS"] =
        lightMask(scene, [](const Light& l) { return l.type != LightType::Directional; });
    defines["SB_SPOT_LIGHTS"] = lightMask(scene, [](const Light& l) { return l.type == LightType::Spot; });
    defines["SB_RANGED_LIGHTS"] =
        lightMask(scene, [](const Light& l) { return l.type != LightType::Directional && l.range > 0.0f; });
    addLightingRateDefines(scene, defines);
}

void addLightingRateDefines(const Scene& scene, Defines& defines) {
    if (scene.lighting != LightingRate::Vertex) return;
    defines["SB_VERTEX_LIGHTING"] = "";
    defines["SB_LIGHT_TERMS"] = std::to_string(std::clamp<int>(int(scene.lights.size()), 1, kMaxLights));
}

Defines withLightKinds(Defines defines, const Scene& scene) {
    addLightKindDefines(scene, defines);
    return defines;
}

void addSceneDefines(const Scene& scene, Defines& defines) {
    if (scene.hasNonReceivers()) defines["SB_NON_RECEIVERS"] = "";
    if (const uint32_t mask = scene.shadowlessLightMask())
        defines["SB_SHADOWLESS_LIGHTS"] = std::to_string(mask) + "u";
    addLightKindDefines(scene, defines);
}

} // namespace sb
