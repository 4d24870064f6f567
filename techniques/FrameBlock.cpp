#include "techniques/FrameBlock.h"

#include <algorithm>
#include <cmath>

namespace sb {

LightConstants lightConstants(const Light& l) {
    return {glm::vec4(l.color * l.intensity, l.range),
            glm::vec2(std::cos(glm::radians(l.spotOuterDeg)), std::cos(glm::radians(l.spotInnerDeg)))};
}

FrameUniformData computeFrameUniforms(const Scene& scene, const glm::mat4& view, const glm::mat4& proj,
                                      const glm::vec3& eye) {
    FrameUniformData d{};
    d.view = view;
    d.proj = proj;
    d.viewProj = proj * view;
    d.eye = glm::vec4(eye, 1.0f);
    int count = std::min<int>(int(scene.lights.size()), kMaxLights);
    d.ambient = glm::vec4(scene.ambient, float(count));
    for (int i = 0; i < count; ++i) {
        const Light& l = scene.lights[size_t(i)];
        float type = l.type == LightType::Directional ? 0.0f : (l.type == LightType::Point ? 1.0f : 2.0f);
        d.lightPos[i] = glm::vec4(l.position, type);
        const LightConstants c = lightConstants(l);
        d.lightDir[i] = glm::vec4(glm::normalize(l.direction), c.coneCos.x);
        d.lightColor[i] = c.colorRange;
        d.lightParams[i] = glm::vec4(c.coneCos.y, 0.0f, 0.0f, 0.0f);
    }
    return d;
}

} // namespace sb
