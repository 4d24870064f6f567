#include "techniques/Technique.h"

#include <algorithm>
#include <string>
#include <vector>

#include "shading/GlslLiteral.h"
#include "shading/ShaderLimits.h"
#include "techniques/FrameBlock.h"

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

/// A GLSL array constant of kMaxLights vecN, light i's `of(light)` at index i and zeros past the scene's
/// lights.
template <int N, typename Of>
std::string lightArray(const Scene& scene, Of of) {
    std::vector<glm::vec<N, float>> values(size_t(kMaxLights), glm::vec<N, float>(0.0f));
    for (size_t i = 0; i < scene.lights.size() && i < values.size(); ++i)
        values[i] = of(lightConstants(scene.lights[i]));
    return glslVecArray<N>(values);
}

} // namespace

std::string ambientDefine(const glm::vec3& ambient) {
    return glslVec<3>(ambient);
}

void addLightKindDefines(const Scene& scene, Defines& defines) {
    defines["SB_STATIC_LIGHTS"] = "";
    defines["SB_AMBIENT"] = ambientDefine(scene.ambient);
    defines["SB_LIGHT_COLORS"] = lightArray<4>(scene, [](const LightConstants& c) { return c.colorRange; });
    defines["SB_LIGHT_CONES"] = lightArray<2>(scene, [](const LightConstants& c) { return c.coneCos; });
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
