#include "scenes/LightFit.h"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

#include "scenes/Math.h"

namespace sb {

const NameTable<Named<LightFitBounds>>& lightFitBoundsNames() {
    static constexpr Named<LightFitBounds> kNames[] = {
        {LightFitBounds::Casters, "casters"},
        {LightFitBounds::Sphere, "sphere"},
        {LightFitBounds::Scene, "scene"},
    };
    static constexpr NameTable kTable{kNames};
    return kTable;
}

namespace {

/// The x and y range (light view space) a directional map frames, before the margin.
Aabb framedBounds(const Scene& scene, const Aabb& casters, const glm::mat4& view, LightFitBounds bounds) {
    switch (bounds) {
    case LightFitBounds::Sphere: {
        // The view looks at the casters' centre, so the sphere is centred on the view's axis.
        const float r = 0.5f * glm::length(casters.extent());
        return Aabb{glm::vec3(-r, -r, 0.0f), glm::vec3(r, r, 0.0f)};
    }
    case LightFitBounds::Scene:
        return transformBounds(scene.computeBounds(false), view);
    case LightFitBounds::Casters:
        break;
    }
    return transformBounds(casters, view); // only casters need to be in the map
}

} // namespace

glm::mat4 fitLightViewProjection(const Scene& scene, const Light& light, const LightFit& fit) {
    Aabb all = scene.computeBounds(false);
    Aabb casters = scene.computeBounds(true);
    if (casters.empty()) casters = all;
    glm::vec3 center = casters.center();
    float radius = std::max(0.5f * glm::length(all.extent()), 1e-3f);
    glm::vec3 dir = glm::normalize(light.direction);
    if (light.type == LightType::Directional) {
        glm::mat4 view = glm::lookAt(center - dir * radius * 2.0f, center, anyPerpendicularUp(dir));
        Aabb xy = framedBounds(scene, casters, view, fit.bounds);
        Aabb z = transformBounds(all, view); // but every receiver must be inside its depth range
        glm::vec2 pad = fit.margin * glm::vec2(xy.extent()) + glm::vec2(1e-3f);
        glm::mat4 proj = glm::ortho(xy.min.x - pad.x, xy.max.x + pad.x, xy.min.y - pad.y, xy.max.y + pad.y,
                                    -z.max.z - 1e-3f * radius, -z.min.z + 1e-3f * radius);
        return proj * view;
    }
    // Spot: perspective frustum with the cone's angle, near/far from the scene's extent along the axis.
    glm::mat4 view = glm::lookAt(light.position, light.position + dir, anyPerpendicularUp(dir));
    Aabb z = transformBounds(all, view);
    float farZ = std::max(-z.min.z, 1e-2f);
    float nearZ = std::clamp(-z.max.z, farZ * 1e-3f, farZ * 0.999f);
    glm::mat4 proj = glm::perspective(glm::radians(2.0f * light.spotOuterDeg), 1.0f, nearZ, farZ);
    return proj * view;
}

} // namespace sb
