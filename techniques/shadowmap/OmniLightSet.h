#pragma once
// The lights of a scene as the omnidirectional shadow-map techniques (`cubemap`, `paraboloid`) map
// them: each point light gets an omni map (six cube faces, or two paraboloid halves) fitted by
// PointLightFit, unless its range reaches no caster (then no map and no depth work: it cannot be
// shadowed, kind None); each spot light the perspective map and each directional light the
// orthographic one that `shadowmap` renders (scenes/LightFit.h, Williams 1978), here called flat maps.
// Also the lighting pass's per-light uniforms, which both techniques' lighting shaders read through
// shaders/shadowmap/omni_lighting.glsl, and the flat maps' depth pass, which is the same for both.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/InstanceCulling.h"
#include "scenes/Scene.h"
#include "shading/ShaderLimits.h"
#include "techniques/MapTexels.h"
#include "techniques/shadowmap/CubeFaces.h"
#include "techniques/shadowmap/PointLightFit.h"

namespace sb {

/// How a technique maps a point light's directions: six cube faces (`cubemap`) or two paraboloid halves
/// (`paraboloid`).
enum class OmniShape { Cube, Paraboloid };

/// How a light is shadowed; the values are omni_lighting.glsl's MAP_* constants.
enum class OmniMapKind : int { None = 0, Flat = 1, Omni = 2 };

struct OmniLight {
    OmniMapKind kind = OmniMapKind::None;
    int index = 0;                ///< among the lights of its kind (the map's slot)
    PointLightFit point;          ///< point lights
    glm::mat4 viewProj{1.0f};     ///< flat maps: the light camera
    glm::mat4 shadowMatrix{1.0f}; ///< flat maps: bias * viewProj (world to [0, 1] texture space)
};

class OmniLightSet final : public MapTexels {
public:
    /// Classifies the first kMaxLights lights of `scene` and fits their cameras (untimed: setScene), for
    /// point-light maps of `shape` and maps (omni and flat) of `resolution` texels a side.
    void setScene(const Scene& scene, OmniShape shape, int resolution);

    const std::vector<OmniLight>& lights() const { return mLights; }
    int omniCount() const { return mOmni; } ///< point lights with a map
    int flatCount() const { return mFlat; }
    int skippedCount() const { return mSkipped; }       ///< point lights whose range reaches no caster
    int unshadowedCount() const { return mUnshadowed; } ///< lights with "casts_shadows": false (no map)
    /// LIGHT_COUNT of the lighting shader (at least 1: GLSL has no empty arrays).
    int shaderLightCount() const { return std::max<int>(1, int(mLights.size())); }

    /// What the lighting pass reads per light (shaderLightCount() entries), on either API: the flat
    /// maps' shadow matrices, each light's map kind and first layer (flat maps at flatBase + index, omni
    /// maps at omniLayers * index) and the omni maps' depth range.
    struct LightingArrays {
        std::vector<glm::mat4> shadowMatrices;
        std::vector<glm::ivec2> maps; ///< (OmniMapKind, layer)
        std::vector<glm::vec2> depthRanges;
    };
    LightingArrays lightingArrays(int flatBase, int omniLayers) const;

    /// The casters flat map `light` draws: those `culling` keeps in its frustum, marked in `keep`.
    /// Returns how many were culled.
    size_t cullFlatCasters(const OmniLight& light, const InstanceCulling& culling,
                           std::vector<uint8_t>& keep) const;

    /// Where the lighting pass looks `at` up (MapTexels): a flat map as omni_lighting.glsl's
    /// flatVisibility (map 0); a point light's cube face (map = face, cube_lighting.frag: the major axis
    /// of the light-to-point vector, by that face's 90-degree perspective camera, CubeFaces) or paraboloid
    /// half (map 0 front, 1 back, paraboloid_lighting.frag: the exact, nonlinear paraboloid projection
    /// of the direction), where the point's distance (major-axis distance for a cube) lies inside the
    /// map's depth range.
    std::optional<MapPoint> texel(size_t light, const ShadedPoint& at, const glm::dvec3& q) const override;
    /// The paraboloid projection of shaders/shadowmap/paraboloid_frame.glsl on the CPU: the light-to-point
    /// vector `v` in texels of hemisphere `half` (0 front, around -Y; 1 back) of a map of `resolution`.
    static glm::dvec2 paraboloidTexel(const glm::dvec3& v, int half, int resolution);

private:
    std::optional<MapPoint> omniTexel(size_t light, const OmniLight& o, const ShadedPoint& at,
                                      const glm::dvec3& q) const;

    std::vector<OmniLight> mLights;
    OmniShape mShape = OmniShape::Cube;
    int mResolution = 0;
    /// Per light (cube shape, point lights with a map): each face's bias * viewProjection.
    std::vector<std::array<glm::mat4, CubeFaces::kFaces>> mCubeShadow;
    int mOmni = 0, mFlat = 0, mSkipped = 0, mUnshadowed = 0;
};

} // namespace sb
