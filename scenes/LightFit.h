#pragma once
// The light camera a shadow map or a projected shadow texture is rendered from, fitted to a scene:
// shared by the flat maps of the shadow-map family (`shadowmap`, `pcss`, `vsm`, `esm`) and `projective`
// (its projector for directional lights). How much of the scene a directional map frames is a choice
// (LightFit): it decides how many map texels a caster covers, so it trades shadow resolution (a tight
// map: more texels per world unit, the fewest wrong pixels) against the depth pass's fill (a loose map:
// the casters cover fewer texels, fewer depth fragments). scenes/MapCoverage.h counts the result.
#include <glm/glm.hpp>

#include "core/NameTable.h"
#include "scenes/Scene.h"

namespace sb {

/// What a directional light's map frames in x and y (light space). Spot lights always take their cone.
enum class LightFitBounds {
    /// The casters' bounding box, the tightest of the three: the most texels per world unit and the
    /// largest share of the map covered (the fit before the choice existed, and the default).
    Casters,
    /// A square around the casters' bounding sphere (centre and half-diagonal of their box): a map of the
    /// same size from every light direction, as a demo that sizes its light frustum to a model's bounding
    /// sphere (glmark2's `shadow` scene) does.
    Sphere,
    /// The bounding box of every instance, receivers included: the loosest, a map that holds the whole
    /// scene (as a world-sized map fixed in advance does).
    Scene,
};

/// The names of the fits, for properties, help and errors: casters, sphere, scene.
const NameTable<Named<LightFitBounds>>& lightFitBoundsNames();

/// How a directional light's camera frames the scene: which bounds, and the margin added on each side.
struct LightFit {
    /// The margin of the fit before it was a choice: 1% of the framed extent on each side.
    static constexpr float kDefaultMargin = 0.01f;
    LightFitBounds bounds = LightFitBounds::Casters;
    /// Added on each side, as a share of the framed extent (plus 1e-3 world units, so that a flat
    /// caster still has a map of non-zero size). 0.5 doubles the map's side: a quarter of the
    /// casters' texels.
    float margin = kDefaultMargin;
};

/// Light view-projection for `light` of `scene` (OpenGL clip conventions). Directional: orthographic
/// along the light, x and y framing `fit.bounds` (above; a scene without casters is framed whole) with
/// `fit.margin` x the framed extent + 1e-3 of padding on each side, the depth range covering every
/// instance, casters and receivers, plus 1e-3 of the scene's radius (a receiver far below is still
/// inside it). Spot: a perspective frustum at the light along its axis with the cone's full angle
/// (2 x spotOuterDeg), far at the scene's deepest point along the axis (at least 1e-2), near at its
/// nearest, kept in [1e-3, 0.999] x far so that it stays positive when the light is inside the scene;
/// `fit` does not apply (the cone is the map). Point lights have no single frustum: callers refuse
/// them or fit their own.
glm::mat4 fitLightViewProjection(const Scene& scene, const Light& light, const LightFit& fit = {});

} // namespace sb
