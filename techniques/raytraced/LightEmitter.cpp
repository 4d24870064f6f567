#include "techniques/raytraced/LightEmitter.h"

#include <cmath>
#include <vector>

#include "shading/GlslLiteral.h"
#include "shading/ShaderLimits.h"

namespace sb {

namespace {

/// The kind of a light LightSampler samples with an extent, from its type and shape (LightSampler::sample's
/// dispatch: every directional light is the sun's cone; a point-shaped light never gets here).
EmitterKind extendedKind(const Light& light) {
    if (light.type == LightType::Directional) return EmitterKind::Cone;
    switch (light.shape) {
    case LightShape::Rect:
        return EmitterKind::Rect;
    case LightShape::Disk:
        return EmitterKind::Disk;
    case LightShape::Sphere:
    case LightShape::Point:
        break;
    }
    return EmitterKind::Sphere;
}

/// LightSampler's delta rule: a point shape, or a zero (or NaN) extent.
bool isDelta(const Light& light) {
    if (light.shape == LightShape::Point) return true;
    if (light.type == LightType::Directional) return !(glm::radians(light.angularRadiusDeg) > 0.0f);
    if (light.shape == LightShape::Rect) return !(light.size.x > 0.0f && light.size.y > 0.0f);
    return !(light.size.x > 0.0f);
}

} // namespace

LightEmitter LightEmitter::of(const Light& light) {
    LightEmitter e;
    if (isDelta(light)) {
        e.kind = light.type == LightType::Directional ? EmitterKind::Direction : EmitterKind::Point;
    } else {
        e.kind = extendedKind(light);
        if (e.kind == EmitterKind::Cone)
            e.constant.w = std::cos(glm::radians(light.angularRadiusDeg));
        else
            e.constant.y = light.size.x;
        if (e.kind == EmitterKind::Rect) e.constant.z = light.size.y;
    }
    e.constant.x = float(int(e.kind));
    return e;
}

void addEmitterDefines(const Scene& scene, Defines& defines) {
    std::vector<glm::vec4> values(size_t(kMaxLights), glm::vec4(0.0f));
    for (size_t i = 0; i < scene.lights.size() && i < values.size(); ++i)
        values[i] = LightEmitter::of(scene.lights[i]).constant;
    defines["SB_EMITTERS"] = glslVecArray<4>(values);
}

} // namespace sb
