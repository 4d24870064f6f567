#pragma once
// The light camera of one cascade of `cascaded`: an orthographic box in the light's frame fitted to a
// slice [d0, d1] of the view frustum, the per-split crop of Zhang et al. 2006 (Parallel-Split Shadow
// Maps for Large-scale Virtual Environments), Engel 2006 (Cascaded Shadow Maps, ShaderX5) and
// Dimitrov 2007 (Cascaded Shadow Maps, NVIDIA whitepaper: the crop matrix of each split).
//
// Stable fit (stabilize = true; the bounding sphere and texel snapping as in Valient 2008, Stable
// Rendering of Cascaded Shadow Maps, ShaderX6, which removes the shimmering of a crop that follows the
// camera): the box's x and y extent is the diameter of the slice's bounding sphere, computed in view
// space from the projection and the two depths alone, so it does not change when the camera turns or
// moves; its radius is rounded up to 1/32 of its power of two so that a slice whose depths drift a
// little keeps its size. The sphere's centre, taken to the light's frame, is snapped down to whole
// texels on all three axes, so the map's texel grid stays fixed in the world while the camera moves
// and a shadow edge is rasterised into the same texels every frame: no shimmer. The box is enlarged
// to h = r * res / (res - 2) per side so that the snapped box (up to one texel off the centre) still
// contains the whole sphere.
//
// Tight fit (stabilize = false): the light-space bounding box of the slice's 8 corners, unsnapped.
// More texels on the slice, but its grid slides with every camera move (the negative control).
//
// Both fits are then kept within the casters' light-frame bounds (the crop to the casters of Zhang
// et al. and Dimitrov): a point outside them in x and y has no caster between it and the light, so a
// map there holds nothing. The tight box is intersected with them; the stable box keeps its size when
// that is smaller than theirs, else takes theirs, and its centre is clamped so that the box still
// holds what they need of it: both are scene constants, so the fit stays as stable as before.
//
// Depth: the box's far side (away from the light) is clipped to the scene's farthest instance, its
// near side put at the nearest caster: casters outside the slice towards the light still shadow it,
// and nothing nearer the light casts (a scene constant, so it costs no stability). The light's frame is a
// rotation about the world origin only (no translation that follows the scene or the camera), so snapping in
// it is snapping in the world.
#include <array>

#include <glm/glm.hpp>

#include "scenes/Mesh.h"

namespace sb {

/// What a directional light's cascades are clipped to, in its light frame (scene constants).
struct CascadeSceneBounds {
    glm::vec2 castersMin{0.0f}, castersMax{-1.0f}; ///< casters' x and y (empty: min > max)
    float castersNear = 0.0f;                      ///< depth of the nearest caster (every box's near side)
    float sceneFar = 0.0f; ///< depth of the farthest instance (the box is clipped to here)
};

/// One fitted cascade.
struct Cascade {
    glm::mat4 lightView{1.0f};               ///< the light's rotation (world -> light frame)
    glm::mat4 viewProj{1.0f};                ///< ortho * lightView: world -> the map's clip space
    glm::vec3 centre{0.0f};                  ///< light frame: the box's centre in x, y (snapped where stable)
    glm::vec3 unsnappedCentre{0.0f};         ///< light frame: the sphere's (stable) or box's (tight) centre
    float halfExtent = 0.0f;                 ///< x and y half size of the box (light frame, world units)
    float texel = 0.0f;                      ///< world units per texel: 2 halfExtent / resolution
    float nearDepth = 0.0f, farDepth = 0.0f; ///< the box's depth range along the light
};

class CascadeFit {
public:
    /// World -> light frame: a rotation looking along `direction` (from the light into the scene),
    /// about the world origin.
    static glm::mat4 lightView(const glm::vec3& direction);

    /// The bounds of the casters' and of all instances' world boxes seen from `lightView` (8 corners
    /// each); no casters: an empty x-y range and castersNear = +max.
    static CascadeSceneBounds sceneBounds(const Aabb& casters, const Aabb& all, const glm::mat4& lightView);

    /// The 4 corners of the view frustum at view depth `depth` (view space: x, y, z = -depth), for a
    /// perspective or orthographic `proj` (with or without an NDC translation).
    static std::array<glm::dvec3, 4> viewCorners(const glm::mat4& proj, float depth);

    /// The slice's bounding sphere in view space (xyz centre, w radius, not yet rounded): the centre on
    /// the segment between the two end faces' centres that minimises the largest corner distance
    /// (exact for a symmetric frustum). Depends on the projection and the depths only.
    static glm::dvec4 sliceSphere(const glm::mat4& proj, float d0, float d1);

    /// The cascade for slice [d0, d1] of the camera (view, proj), light frame `lightView`, a square
    /// map of `resolution` texels, stable or tight fit (see above).
    static Cascade fit(const glm::mat4& lightView, const glm::mat4& view, const glm::mat4& proj, float d0,
                       float d1, const CascadeSceneBounds& bounds, int resolution, bool stabilize);

    /// r rounded up to a multiple of 2^(floor(log2 r) - 5): at most 1/32 larger.
    static double roundRadius(double r);
};

} // namespace sb
