#pragma once
// The depth range of an omnidirectional shadow map at a point light, shared by `cubemap` (its six
// faces) and `paraboloid` (its two hemispheres). Far: the light's range when it has one (nothing
// beyond it is lit, so nothing beyond it needs to cast), capped at the scene's farthest point from the
// light; with no range, that farthest point (every instance's bounds inside the map). Near: a small
// fraction of the scene (1e-3 of its bounding radius), at most 1e-2 of far, so that 24-bit depth keeps
// sub-millimetre steps at the far end of a room-sized scene while a caster close to the light is
// still in front of the near plane. A light whose range reaches no caster casts no shadow: it needs
// no map at all (castsShadow false, the techniques skip its depth work and count it).
#include <glm/glm.hpp>

#include "scenes/Scene.h"

namespace sb {

struct PointLightFit {
    glm::vec3 position{0.0f};
    float nearZ = 0.0f;
    float farZ = 0.0f;
    /// Some caster's bounds reach within farZ of the light (and within its range, if any).
    bool castsShadow = false;

    /// The fit for `light` (a point light) of `scene`.
    static PointLightFit fit(const Scene& scene, const Light& light);
    /// Distance from `p` to the nearest point of `box` (0 inside); the range test of every caster.
    static float distanceToBox(const glm::vec3& p, const Aabb& box);
};

} // namespace sb
