#include "techniques/FrameBlock.h"

#include <algorithm>
#include <cmath>

namespace sb {

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
        d.lightDir[i] = glm::vec4(glm::normalize(l.direction), std::cos(glm::radians(l.spotOuterDeg)));
        d.lightColor[i] = glm::vec4(l.color * l.intensity, l.range);
        d.lightParams[i] = glm::vec4(std::cos(glm::radians(l.spotInnerDeg)), 0.0f, 0.0f, 0.0f);
    }
    return d;
}

} // namespace sb
