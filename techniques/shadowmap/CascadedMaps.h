#pragma once
// What `cascaded` computes on the CPU, on both APIs (CascadedGL, CascadedVulkan): the shadowed lights
// and their slots (a directional light's cascades, a spot light's one map), each frame's splits and
// fits (CascadeSplits, CascadeFit), which cascades share a map, which slots are empty, the depth pass's
// plan (the maps to draw, their casters culled), the lighting pass's split values and defines, and the
// counters. The API forms only record: they draw the maps this class hands them and upload its values.
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/InstanceCulling.h"
#include "scenes/Scene.h"
#include "shading/Defines.h"
#include "techniques/MapTexels.h"
#include "techniques/PropertySet.h"
#include "techniques/Submission.h"
#include "techniques/TechniqueInfo.h"
#include "techniques/shadowmap/CascadeFit.h"

namespace sb {

class CascadedMaps final : public MapTexels {
public:
    /// The lighting pass's per-cascade values (cascaded_lighting.frag's uSplitFar, uBandStart, uBandScale).
    struct SplitValues {
        glm::vec4 splitFar, bandStart, bandScale;
    };

    /// The first kMaxLights lights of `scene` with `cascades` cascades per directional light (refuses a
    /// point light that casts: PointLightRefusal), the receivers' bounds and the caster culling.
    void setScene(const Scene& scene, int cascades);
    /// Slots of every light (at least 1: GLSL has no empty arrays); layer i of the depth array is slot i's.
    int slotCount() const;
    /// This frame's splits and fits for the camera (view, proj; GL conventions), maps of `resolution`^2.
    /// fit=sdsm: `samples` is the view-depth interval of the pixels the depth pre-pass covered (x > y:
    /// none), the reduction's answer (CascadeSplits::sampleDistribution splits it); practical ignores it.
    void fit(const glm::mat4& view, const glm::mat4& proj, const PropertySet& p, int resolution,
             glm::vec2 samples = glm::vec2(1.0f, 0.0f));
    /// The depth pass: for each map to draw this frame, its casters culled into `keep` and `draw(slot)`
    /// called (its layer is the slot). Empty and shared slots are marked, not drawn. Returns maps drawn.
    int planDepth(std::vector<uint8_t>& keep, const std::function<void(size_t slot)>& draw);
    /// The lighting pass's split values for `p`'s cascades and blend (no splits yet: no cascade ends).
    SplitValues splitValues(const PropertySet& p) const;
    /// The lighting pass's defines: `scene` (the submitter's and the scene's shadow exceptions) plus the
    /// lights' slots, the cascade count, blending and the PCF width.
    Defines lightingDefines(Defines scene, const PropertySet& p) const;
    /// The counters of a frame, on both APIs: DepthLightingFrame's over the maps drawn at `resolution`,
    /// then cascades, casters culled and lights unshadowed; fit=sdsm adds the view-depth interval the
    /// reduction found (depth_min, depth_max; 0 and 0 when no pixel was covered).
    Counters counters(const SubmitStats& s, int resolution, const Scene& scene, const PropertySet& p) const;

    const std::vector<float>& splits() const { return mSplits; }
    const std::vector<Cascade>& cascades(size_t light) const { return mLights[light].cascades; }
    const std::vector<glm::mat4>& slotViewProj() const { return mSlotViewProj; } ///< world -> map clip
    const std::vector<glm::mat4>& slotShadow() const { return mSlotShadow; }     ///< bias * viewProj
    const std::vector<int>& slotLayer() const { return mSlotLayer; }
    uint32_t emptySlots() const { return mEmptySlots; } ///< bit per slot: no caster in its map, lit

    /// The slot cascaded_lighting.frag looks `at` up in (MapTexels): a directional light's cascade c (map
    /// c), the first whose far split lies beyond `at`'s view depth in the last fit()'s camera, or a spot
    /// light's one map (map 0); none in an empty slot. In a blend band the pass also reads cascade c + 1,
    /// whose texels are larger: the answer is cascade c's.
    std::optional<MapPoint> texel(size_t light, const ShadedPoint& at, const glm::dvec3& q) const override;

private:
    /// A shadowed light: its slots and how they are fitted.
    struct LightMaps {
        bool directional = true;
        bool castsShadows = true; ///< false: its slots are never drawn (empty: the lookup says lit)
        int firstSlot = 0;
        int slots = 1;                 ///< cascades (directional) or 1 (spot)
        glm::mat4 lightView{1.0f};     ///< directional: the light's rotation
        CascadeSceneBounds bounds;     ///< directional: what its cascades are clipped to
        glm::mat4 spotViewProj{1.0f};  ///< spot: the fitted perspective map
        std::vector<Cascade> cascades; ///< directional: this frame's fits
    };
    void shareIdenticalFits(const LightMaps& m);

    std::vector<LightMaps> mLights;
    std::vector<Aabb> mReceivers;   ///< world bounds of every receiving instance
    std::vector<float> mSplits;     ///< this frame's split distances (view depth)
    glm::vec2 mSamples{1.0f, 0.0f}; ///< fit=sdsm: the view-depth interval the frame was split from
    glm::mat4 mView{1.0f};          ///< this frame's camera (fit()), for a sample's view depth
    int mResolution = 0;            ///< this frame's maps' resolution (fit())
    std::vector<float> mFitStart;   ///< where each cascade's fit starts (its blend band included)
    // Per slot (a light's cascade, or a spot light's one map; slot i may use layer i at most):
    std::vector<glm::mat4> mSlotViewProj; ///< world -> the map's clip space
    std::vector<glm::mat4> mSlotShadow;   ///< bias * viewProj (to [0, 1] texture space)
    std::vector<int> mSlotLayer;          ///< the depth array's layer it reads (shared when identical)
    uint32_t mEmptySlots = 0;             ///< bit per slot: no caster reaches its map this frame
    int mMapsRendered = 0;                ///< distinct maps drawn last frame
    InstanceCulling mCulling;
    size_t mCulled = 0; ///< casters culled, summed over the maps drawn, last frame
};

} // namespace sb
