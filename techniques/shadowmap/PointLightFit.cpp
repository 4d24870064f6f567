#include "techniques/shadowmap/PointLightFit.h"

#include <algorithm>
#include <limits>

#include "scenes/Math.h"

namespace sb {

float PointLightFit::distanceToBox(const glm::vec3& p, const Aabb& box) {
    if (box.empty()) return std::numeric_limits<float>::infinity();
    const glm::vec3 nearest = glm::clamp(p, box.min, box.max);
    return glm::length(p - nearest);
}

PointLightFit PointLightFit::fit(const Scene& scene, const Light& light) {
    PointLightFit f;
    f.position = light.position;
    const Aabb all = scene.computeBounds(false);
    float farthest = 0.0f;
    if (!all.empty())
        for (const glm::vec3& c : all.corners())
            farthest = std::max(farthest, glm::length(c - light.position));
    // 1% beyond the farthest corner, so that a receiver exactly there is still inside the far plane.
    farthest = std::max(1.01f * farthest, 1e-3f);
    f.farZ = light.range > 0.0f ? std::min(light.range, farthest) : farthest;
    const float radius = all.empty() ? 1.0f : std::max(0.5f * glm::length(all.extent()), 1e-3f);
    f.nearZ = std::min(1e-3f * radius, 1e-2f * f.farZ);
    for (const Instance& inst : scene.instances) {
        if (!inst.castsShadow || inst.mesh >= scene.meshes.size()) continue;
        const Aabb box = transformBounds(scene.meshBoundsOf(inst.mesh), inst.model);
        if (distanceToBox(light.position, box) < f.farZ) {
            f.castsShadow = true;
            break;
        }
    }
    return f;
}

} // namespace sb
