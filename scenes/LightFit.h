#pragma once
// The light camera a shadow map or a projected shadow texture is rendered from, fitted to a scene:
// shared by `shadowmap` (its depth maps) and `projective` (its projector for directional lights).
#include <glm/glm.hpp>

#include "scenes/Scene.h"

namespace sb {

/// Light view-projection for `light` of `scene` (OpenGL clip conventions). Directional: orthographic
/// along the light, x and y fitted to the casters' bounds with 1% + 1e-3 of padding each side (only
/// casters need to be in the map; a scene without casters is fitted whole), the depth range covering
/// every instance, casters and receivers, plus 1e-3 of the scene's radius (a receiver far below is
/// still inside it). Spot: a perspective frustum at the light along its axis with the cone's full
/// angle (2 x spotOuterDeg), far at the scene's deepest point along the axis (at least 1e-2), near at
/// its nearest, kept in [1e-3, 0.999] x far so that it stays positive when the light is inside the
/// scene. Point lights have no single frustum: callers refuse them or fit their own.
glm::mat4 fitLightViewProjection(const Scene& scene, const Light& light);

} // namespace sb
