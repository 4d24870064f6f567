#pragma once
// `pcss`: percentage-closer soft shadows (Fernando 2005, Percentage-Closer Soft Shadows, SIGGRAPH sketch).
// The declaration (techniques/TechniqueInfo.h) its GL and Vulkan forms both take: name, effects, the
// capabilities of each API's form, passes, properties and quality knobs; and what both forms compute
// per light for the lighting pass (LightParams, techniques/shadowmap/PcssGL.h has the derivation).
#include <glm/glm.hpp>

#include <vector>

#include "scenes/Scene.h"
#include "techniques/FlatLightFits.h"
#include "techniques/Submission.h"
#include "techniques/TechniqueInfo.h"

namespace sb {

struct Pcss {
    static constexpr const char* kBlockerTaps = "blocker_taps";
    static constexpr const char* kFilterTaps = "filter_taps";
    static constexpr const char* kLightSize = "light_size";
    static constexpr int kMaxTaps = 64;

    /// Angular radius of the emitter a light with no extent is given (degrees): a 1 degree disk.
    static constexpr float kDefaultAngularRadiusDeg = 0.5f;

    static TechniqueInfo declaration();

    /// What the shader needs of one light's map: L (light size), whether the map is perspective, its near
    /// and far planes (orthographic: 0 and far - near, depth measured from the near plane), the world
    /// extent of the map along its u and v axes (perspective: at depth 1) and the linear depth of the
    /// nearest caster (the casters' bounds' nearest corner, within [near, far]).
    struct LightParams {
        float size = 0.0f;
        bool perspective = false;
        float nearZ = 0.0f, farZ = 1.0f;
        glm::vec2 extent{1.0f};
        float nearestCaster = 0.0f;
        bool defaulted = false; ///< the light had no extent: the 1 degree default
    };
    /// The parameters of light `light` of `scene` rendered with `lightViewProj` (scenes/LightFit.h), with
    /// `sizeOverride` > 0 replacing the scene's light size. Public for the tests' closed forms.
    static LightParams lightParams(const Scene& scene, const Light& light, const glm::mat4& lightViewProj,
                                   float sizeOverride);
    /// The lighting pass's per-light vectors (shaders/shadowmap/pcss.frag): uPcssLight (L, perspective,
    /// near, far) and uPcssSearch (the map's extent, the nearest caster's depth).
    static glm::vec4 lightVector(const LightParams& lp);
    static glm::vec4 searchVector(const LightParams& lp);
    /// The frame's counters on either API: draw_calls and triangles of `s`, the maps' texels, unshadowed
    /// lights (of `fits`), culled casters, the kernels' taps, light 0's size, the lights given the
    /// default size and the share of the maps the casters cover (FlatLightFits::coverage).
    static Counters counters(const SubmitStats& s, int mapSize, const FlatLightFits& fits, size_t culled,
                             size_t blockerTaps, size_t filterTaps, const std::vector<LightParams>& params);
    /// The filter's Poisson disk differs from the search's: its seed (techniques/shadowmap/PoissonDisk.h).
    static uint64_t filterSeed();
};

} // namespace sb
