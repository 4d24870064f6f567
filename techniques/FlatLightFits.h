#pragma once
// The flat light cameras of `shadowmap` and `pcss`: per light of a scene (at most kMaxLights) the
// orthographic (directional) or perspective (spot) camera fitted to the scene (scenes/LightFit.h,
// Williams 1978) as the technique's `fit` and `fit_margin` ask, the share of the maps the casters cover
// (scenes/MapCoverage.h), the shadow matrix that takes world positions to the map's [0, 1] texture space, and
// the casters each light's depth pass draws (one map layer per light: techniques/shadowmap/FlatLightsGL.h
// on GL, techniques/vulkan/VulkanDepthMapSet.h on Vulkan). Point lights need an omni map and are refused
// here with the words every flat map uses (techniques/PointLightRefusal.h), or, for a technique that
// answers them another way, left without a map (PointLights::Unmapped). Both members fit, render and
// refuse alike; keeping it in one place keeps their maps, counters and messages identical. It lives below
// the technique folders so that a technique outside the family can render the same maps.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/InstanceCulling.h"
#include "scenes/LightFit.h"
#include "scenes/MapCoverage.h"
#include "scenes/Scene.h"
#include "shading/ShaderLimits.h"
#include "techniques/MapTexels.h"
#include "techniques/PropertySet.h"

namespace sb {

/// The view a light's casters must reach to be drawn into its map (shadowmap's `cull`): the scene's
/// lights, the camera and the receivers, and per light the world margin the lighting pass's filter
/// reads around a texel (InstanceCulling::keepReachingView).
struct ViewCull {
    const std::vector<Light>* lights = nullptr;
    ViewReach reach;
    std::vector<float> margins; ///< per light, world units
};

class FlatLightFits final : public MapTexels {
public:
    /// World size of one texel of a map of `resolution` texels rendered with `lightViewProj`, at
    /// light-space w = 1: row r of an orthographic proj * view is (2 / extent_r) times a unit axis, and
    /// of a perspective one (2 / (2 tan(fov / 2))) times it with extent growing with w. The larger of
    /// the two axes.
    static float texelWorldSize(const glm::mat4& lightViewProj, int resolution);
    /// The largest light-space w over the corners of `bounds` (1 for an orthographic map): how much a
    /// perspective map's texels grow out to the farthest of them.
    static float farthestW(const glm::mat4& lightViewProj, const Aabb& bounds);
    /// Clip space to [0, 1] texture space: scale by one half, translate by one half.
    static const glm::mat4& textureBias();
    /// What setScene does with a point light that casts shadows, which no flat map can hold: refuse it
    /// (the family's flat maps), or leave it without a map (castsShadow false, its matrices unused) for a
    /// technique that answers its shadow without one.
    enum class PointLights { Refuse, Unmapped };

    /// Fits every light's camera (untimed: setScene) with the fit `p` asks for (LightFitProperties::
    /// lightFit), refusing point lights that cast shadows in `technique`'s name (PointLightRefusal::
    /// refuse; a point light with "casts_shadows": false only illuminates: its matrix is unused) unless
    /// `points` is Unmapped, and counts the texels the casters cover in maps of `p`'s resolution. A scene
    /// in motion calls this in every timed frame (Technique::sceneChanged): there the coverage is counted
    /// once, at the pose the run was prepared at, so that the count's CPU work stays out of the measured
    /// frames.
    void setScene(const Scene& scene, const std::string& technique, const PropertySet& p,
                  PointLights points = PointLights::Refuse);
    /// The same for a technique without the fit's knobs: `fit` and maps of `resolution` texels.
    void setScene(const Scene& scene, const std::string& technique, const LightFit& fit, int resolution,
                  PointLights points);

    size_t size() const { return mViewProj.size(); }
    /// The maps' resolution (setScene's).
    int resolution() const { return mResolution; }
    /// Light `light`'s one map (map 0), where lighting.frag looks `at` up (MapTexels). pcss's blocker search
    /// also reads a little past the map's edge; its samples there are left out.
    std::optional<MapPoint> texel(size_t light, const ShadedPoint& at, const glm::dvec3& q) const override;
    /// The shadowed lights' maps together: texels the casters cover, and all their texels
    /// (counter_map_covered_pct).
    const MapCoverage& coverage() const { return mCoverage; }
    /// The lights that have a map (they cast shadows; their layers are rendered): the texel counters
    /// count these.
    size_t shadowed() const;
    const std::vector<glm::mat4>& viewProj() const { return mViewProj; }           ///< per light
    const std::vector<glm::mat4>& shadowMatrices() const { return mShadowMatrix; } ///< bias * viewProj

    /// Whether light `light` casts shadows through its map (its map is drawn; an unshadowed light's
    /// layer, or an unmapped point light's, is neither cleared nor read).
    bool castsShadow(size_t light) const { return mCastsShadows[light] != 0; }
    /// The casters light `light`'s depth pass draws, on either API: those `culling` keeps in its
    /// frustum and, with `view`, of those only the ones whose shadow may reach the view, marked in
    /// `keep`. Returns how many were culled.
    size_t cullCasters(size_t light, const InstanceCulling& culling, std::vector<uint8_t>& keep,
                       const ViewCull* view = nullptr) const;

private:
    std::vector<glm::mat4> mViewProj;
    std::vector<glm::mat4> mShadowMatrix;
    std::vector<uint8_t> mCastsShadows; ///< per light
    int mResolution = 0;
    MapCoverage mCoverage;
    bool mCoverageCounted = false; ///< a scene in motion counts once (setScene)
};

} // namespace sb
