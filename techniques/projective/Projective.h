#pragma once
// `projective`: projective texture shadows, after Crawfis, Ad-hoc shadows (CSE 781 slides).
// The declaration (techniques/TechniqueInfo.h) its GL and Vulkan forms both take: name, effects, the
// capabilities of each API's form, passes, properties and quality knobs; and what both forms compute
// alike on the CPU: the projectors (techniques/projective/ProjectiveGL.h says how they are fitted) and
// the counters.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/LightFit.h"
#include "scenes/Scene.h"
#include "techniques/PropertySet.h"
#include "techniques/Submission.h"
#include "techniques/Technique.h"
#include "techniques/TechniqueInfo.h"

namespace sb {

struct Projective {
    static constexpr const char* kBlur = "blur";
    static constexpr const char* kCull = "cull";
    static constexpr const char* kResolution = "resolution";

    static TechniqueInfo declaration();

    /// The widest projector half-angle (degrees): a projector that would need a wider frustum (one
    /// reaching 90 degrees or more) gets this one.
    static constexpr float kMaxHalfAngleDeg = 80.0f;

    /// A light's projector: view-projection of the light camera (GL clip space) and whether its frustum
    /// was clamped to kMaxHalfAngleDeg.
    struct Projector {
        glm::mat4 viewProj{1.0f};
        bool clamped = false;
    };
    /// The projector of `light` for `scene` (whose casters must not be empty); `fit` frames a
    /// directional light's (point and spot lights aim at the casters' bounding sphere).
    static Projector computeProjector(const Scene& scene, const Light& light, const LightFit& fit = {});
    /// A point or spot light's projector aimed at `receivers` (world bounds, not empty): from the
    /// light towards their centre, the half-angle to their farthest corner (at most
    /// kMaxHalfAngleDeg), far at their deepest corner.
    static Projector aimAtReceivers(const Light& light, const Aabb& receivers);

    /// Every light's projector for a scene.
    struct Plan {
        std::vector<glm::mat4> viewProj;      ///< per light with a projector: light camera (clip space)
        std::vector<glm::mat4> textureMatrix; ///< per light: bias * viewProj (to [0,1] texture space)
        std::vector<uint8_t> castsShadows;    ///< per light: false leaves its layer undrawn
        int clamped = 0;                      ///< lights whose projector was clamped
        const char* noProjector = nullptr;    ///< why the scene needs none (ShadowWork), or nullptr
        Aabb receivers;                       ///< the non-casters' bounds: where shadows can fall
    };
    /// The plan of `scene`: a directional light's projector is the shadow map's light camera
    /// (scenes/LightFit.h), framed as `properties`' `fit` and `fit_margin` ask
    /// (techniques/LightFitProperties.h).
    static Plan plan(const Scene& scene, const PropertySet& properties);

    /// The counters of a frame.
    static Counters counters(const SubmitStats& s, const Scene& scene, int resolution,
                             const std::vector<uint8_t>& castsShadows, int blurPasses, int clamped,
                             size_t culled);
};

} // namespace sb
