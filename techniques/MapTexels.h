#pragma once
// Where a shadow-map technique's lighting pass looks a world point up: for one light, which of its maps
// shades the point (a cascade, a cube face, a paraboloid half, or the light's one map), that map's
// resolution, and where a point lies in it, in texels. The accuracy judge differentiates it across the
// receiver's surface to count the map's texels per screen pixel (bench/lib/measure/TexelDensity.h, after
// Lloyd et al.'s aliasing error). Each family answers once, in the API-neutral class both of its forms
// hold: FlatLightFits (shadowmap, pcss), MomentMapFits (vsm, esm), CascadedMaps (cascaded) and
// OmniLightSet (cubemap, paraboloid), so a technique's GL and Vulkan forms answer identically
// (Technique::mapTexels); hybrid answers with each instance's role's technique.
#include <cstddef>
#include <cstdint>
#include <optional>

#include <glm/glm.hpp>

namespace sb {

/// A shaded sample: its world position and the instance it lies on (an index into Scene::instances).
struct ShadedPoint {
    glm::dvec3 position{0.0};
    uint32_t instance = 0;
};

/// A point's place in one map of a light.
struct MapPoint {
    /// Which of the light's maps: its cascade, cube face (0-5, GL's face order) or paraboloid half (0
    /// front, 1 back); 0 for a light's one map.
    int map = 0;
    int resolution = 0;    ///< texels per side of that map
    glm::dvec2 texel{0.0}; ///< position in texels: [0, resolution]^2 inside the map
};

class MapTexels {
public:
    virtual ~MapTexels() = default;

    /// Where `q` lies in the map of light `light` that the lighting pass reads for the sample `at`, by that
    /// map's own mapping extended past its edges (so that points around `at` are placed in the map `at`
    /// chose, as a finite difference needs). Nothing where the pass reads no map for `at`: the light has
    /// none (it casts no shadow, a flat map's point light, a light beyond the shader's limit, a cascade
    /// no caster reaches) or `at` lies outside the map's area or depth range, which the pass calls lit
    /// without a lookup.
    virtual std::optional<MapPoint> texel(size_t light, const ShadedPoint& at, const glm::dvec3& q) const = 0;

    /// For the projective maps (orthographic and perspective, `shadow` = bias * viewProj, world to [0, 1]
    /// texture space): whether the lighting pass looks `p` up, as shaders/shadowmap/lighting.frag decides:
    /// in front of the light, inside [margin, 1 - margin]^2 in texture space and, with `clipFar`, not
    /// beyond the far plane (the filterable maps' light_depth.glsl has a margin and no far test).
    static bool looksUp(const glm::mat4& shadow, const glm::dvec3& p, double margin = 0.0,
                        bool clipFar = true);
    /// `q` in texels of such a map of `resolution` texels: (shadow * q).xy / w * resolution, in double.
    static glm::dvec2 projectedTexel(const glm::mat4& shadow, int resolution, const glm::dvec3& q);
};

} // namespace sb
