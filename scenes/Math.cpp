#include "scenes/Math.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace sb {

glm::mat4 composeTransform(const glm::vec3& position, const glm::vec3& rotationDeg, float scale) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), position);
    m = glm::rotate(m, glm::radians(rotationDeg.x), glm::vec3(1, 0, 0));
    m = glm::rotate(m, glm::radians(rotationDeg.y), glm::vec3(0, 1, 0));
    m = glm::rotate(m, glm::radians(rotationDeg.z), glm::vec3(0, 0, 1));
    return glm::scale(m, glm::vec3(scale));
}

Aabb transformBounds(const Aabb& b, const glm::mat4& m) {
    Aabb out;
    if (b.empty()) return out;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? b.max.x : b.min.x, (corner & 2) ? b.max.y : b.min.y,
                          (corner & 4) ? b.max.z : b.min.z);
        out.extend(glm::vec3(m * glm::vec4(p, 1.0f)));
    }
    return out;
}

glm::mat4 cameraProjection(const CameraPreset& c, float aspect) {
    return glm::perspective(glm::radians(c.fovYDeg), aspect, c.nearZ, c.farZ);
}

glm::mat4 cameraView(const CameraPreset& c) {
    return glm::lookAt(c.eye, c.target, c.up);
}

glm::vec3 anyPerpendicularUp(const glm::vec3& dir) {
    // World up unless the direction is (nearly) vertical; then +Z, which is then far from parallel.
    const glm::vec3 d = glm::normalize(dir);
    return std::abs(d.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1);
}

namespace {

/// Min/max of the 8 corners of `b` in the space of `view`.
Aabb viewSpaceBounds(const Aabb& b, const glm::mat4& view) {
    return transformBounds(b, view);
}

/// A degenerate box (a point, a flat ground plane seen edge-on) still needs a non-zero volume.
Aabb padded(Aabb b) {
    const float size = std::max(glm::length(b.extent()), 1e-3f);
    const glm::vec3 pad = glm::max(b.extent() * 1e-4f, glm::vec3(size * 1e-5f));
    b.min -= pad;
    b.max += pad;
    return b;
}

glm::mat4 fitDirectional(const Light& light, const Aabb& bounds) {
    const glm::vec3 dir = glm::normalize(light.direction);
    const float radius = std::max(0.5f * glm::length(bounds.extent()), 1e-3f);
    const glm::vec3 centre = bounds.center();
    // The eye sits outside the bounding sphere so every corner has negative view z (in front).
    const glm::mat4 view = glm::lookAt(centre - dir * (2.0f * radius), centre, anyPerpendicularUp(dir));
    // Tight fit: the transformed corners, not the sphere, so texels are not wasted.
    const Aabb v = padded(viewSpaceBounds(bounds, view));
    return glm::ortho(v.min.x, v.max.x, v.min.y, v.max.y, -v.max.z, -v.min.z) * view;
}

glm::mat4 fitSpot(const Light& light, const Aabb& bounds) {
    const glm::vec3 dir = glm::normalize(light.direction);
    const glm::mat4 view = glm::lookAt(light.position, light.position + dir, anyPerpendicularUp(dir));
    const Aabb v = viewSpaceBounds(bounds, view);
    // Depth in front of the light is -z. The near plane must stay positive even when the bounds
    // surround the light; 1e-4 of the far distance keeps depth precision usable.
    float farZ = std::max(-v.min.z, 1e-2f) * 1.01f;
    float nearZ = std::max(-v.max.z * 0.99f, farZ * 1e-4f);
    if (nearZ >= farZ) nearZ = farZ * 0.5f;
    const float fovY = std::clamp(2.0f * light.spotOuterDeg, 1.0f, 179.0f);
    return glm::perspective(glm::radians(fovY), 1.0f, nearZ, farZ) * view;
}

} // namespace

glm::mat4 fitLightViewProjection(const Light& light, const Aabb& bounds) {
    Aabb b = bounds;
    if (b.empty()) b.extend(glm::vec3(0.0f));
    return light.type == LightType::Spot ? fitSpot(light, b) : fitDirectional(light, b);
}

} // namespace sb
