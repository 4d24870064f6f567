#pragma once
// The API-neutral part of the filterable shadow maps (`vsm`, `esm`), which their GL form
// (techniques/shadowmap/FilterableShadowMaps.h, where the method is described: linear light-space depth,
// the receiver background, the margin, the culling) and their Vulkan form (techniques/shadowmap/
// VulkanMomentMaps.h) share: per light the fitted camera widened by the margin, the shadow matrix, the
// linear depth's parameters, which casters (and which background non-casters) a light's pass draws, and
// the frame's counters.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/InstanceCulling.h"
#include "scenes/LightFit.h"
#include "scenes/MapCoverage.h"
#include "scenes/Scene.h"
#include "techniques/MapTexels.h"
#include "techniques/PropertySet.h"
#include "techniques/Submission.h"
#include "techniques/TechniqueInfo.h"

namespace sb {

class MomentMapFits final : public MapTexels {
public:
    explicit MomentMapFits(std::string owner) : mOwner(std::move(owner)) {}

    /// Fits a light camera per light (at most kMaxLights, scenes/LightFit.h) with the fit `p` asks for
    /// (its `fit` and `fit_margin`, LightFitProperties::lightFit); throws Error(Unsupported) naming the
    /// omni techniques for a point light.
    void setScene(const Scene& scene, const PropertySet& p);
    /// A scene in motion moved: the light fits again, then the maps fitted as the last fit() did.
    void sceneChanged(const Scene& scene);
    /// The light cameras for maps of `resolution` texels with a border of `marginTexels`, the depth
    /// parameters for them and the texels the casters cover (coverage(); of a scene in motion counted
    /// once, at the pose the run was prepared at: FlatLightFits::setScene says why). Cheap when nothing
    /// changed. A margin above a quarter of the resolution is
    /// refused (Error(BadInput)): the casters would keep less than half the map.
    void fit(const Scene& scene, int resolution, int marginTexels);

    /// Whether a light's pass draws the non-casters as the map's background. Default true.
    void setReceiverBackground(bool on) { mReceiverBackground = on; }
    /// Leave out of each light's map the casters whose shadow, grown by the filter's reach, cannot
    /// reach the view (vsm's and esm's `cull`).
    void setViewCull(bool on) { mViewCull = on; }

    /// What light `light`'s pass draws, for the camera `cameraViewProj` (projection * view): the casters
    /// kept in `keep` (their count in `casters`, the culled ones added to `culled`) and, where the
    /// receiver background is on and any caster is kept, the non-casters in `keepBackground`
    /// (`background`).
    struct LightDraws {
        size_t casters = 0;
        bool background = false;
    };
    LightDraws cull(size_t light, const Scene& scene, const glm::mat4& cameraViewProj,
                    std::vector<uint8_t>& keep, std::vector<uint8_t>& keepBackground, size_t& culled) const;

    size_t lights() const { return mFitted.size(); }
    /// The lights that cast shadows (their layers are rendered and blurred).
    size_t shadowedLights() const;
    bool castsShadow(size_t light) const { return mCastsShadows[light] != 0; }
    int marginTexels() const { return mMarginTexels; }
    /// The margin in texture coordinates of a map of `resolution` texels (light_depth.glsl's margin).
    float marginUv(int resolution) const { return float(mMarginTexels) / float(resolution); }

    /// Linear light-space depth parameters (light_depth.glsl): directional lights a plane (the receiver's
    /// d = dot(plane.xyz, p) + plane.w) with point.w = 0; spot lights the light's position and 1 / dMax
    /// in point (d = |p - point.xyz| * point.w).
    const std::vector<glm::vec4>& depthPlanes() const { return mDepthPlane; }
    const std::vector<glm::vec4>& depthPoints() const { return mDepthPoint; }
    /// The same d on the CPU (tests).
    static float linearDepth(const glm::vec4& plane, const glm::vec4& point, const glm::vec3& p);
    const std::vector<glm::mat4>& viewProjections() const { return mViewProj; }
    /// bias * viewProj per light: what common/scene.vert projects the receivers with.
    const std::vector<glm::mat4>& shadowMatrices() const { return mShadowMatrix; }

    /// The shadowed lights' maps together: texels the casters cover, and all their texels.
    const MapCoverage& coverage() const { return mCoverage; }

    /// Light `light`'s one map (map 0) at the last fit()'s resolution, where light_depth.glsl's
    /// mapCoordinate looks `at` up: inside the margin (MapTexels).
    std::optional<MapPoint> texel(size_t light, const ShadedPoint& at, const glm::dvec3& q) const override;

    /// The frame's counters on either API: draw_calls, triangles, shadow_map_texels, lights_unshadowed,
    /// blur_texels, casters_culled, map_covered_pct.
    Counters counters(const SubmitStats& s, int resolution, double blurTexels, size_t culled) const;

private:
    /// setScene's work with the fit already read (mFit): what a scene in motion repeats.
    void fitLights(const Scene& scene);

    std::string mOwner;                 ///< technique name, for error messages
    std::vector<glm::mat4> mFitted;     ///< per light: scenes/LightFit.h's camera, before the margin
    std::vector<uint8_t> mCastsShadows; ///< per light
    std::vector<uint8_t> mDirectional;
    std::vector<glm::vec3> mLightPosition;
    int mFitResolution = 0, mMarginTexels = -1;
    bool mViewCull = true;
    bool mReceiverBackground = true;
    Aabb mReceiverBounds; ///< what can receive a shadow (setScene), for mViewCull
    std::vector<glm::mat4> mViewProj, mShadowMatrix;
    std::vector<glm::vec4> mDepthPlane, mDepthPoint;
    InstanceCulling mCulling;
    LightFit mFit;
    MapCoverage mCoverage;
    bool mCoverageCounted = false; ///< a scene in motion counts once
};

} // namespace sb
