#pragma once
// `shadowmap`: two-pass shadow mapping (Williams 1978, Casting curved shadows on curved surfaces).
// The declaration (techniques/TechniqueInfo.h) its GL and Vulkan forms both take: name, effects, the
// capabilities of each API's form, passes, properties and quality knobs.
#include <vector>

#include <glm/glm.hpp>

#include "shading/Defines.h"
#include "techniques/FlatLightFits.h"
#include "techniques/PropertySet.h"
#include "techniques/Submission.h"
#include "techniques/TechniqueInfo.h"

namespace sb {

struct ShadowMap {
    static constexpr const char* kCull = "cull";
    static constexpr const char* kHardwareCompare = "hardware_compare";
    static constexpr const char* kKernel = "kernel";
    static constexpr const char* kNormalOffset = "normal_offset";
    static constexpr const char* kRadius = "radius";
    static constexpr const char* kReceiverPlane = "receiver_plane";
    static constexpr const char* kTaps = "taps";

    static TechniqueInfo declaration();
    /// The lighting pass's defines on either API: `scene` (the submitter's and the scene's shadow
    /// exceptions) plus the map's and the kernel's, for `layers` maps. Defaults add no define: the default
    /// program is the one before these knobs existed; the non-grid kernels take their taps as uniforms and
    /// ignore pcf, so neither `taps` nor `pcf` multiplies their programs.
    static Defines lightingDefines(Defines scene, const PropertySet& p, int layers);
    /// The kernel's tap offsets in texels for `p` (empty: the grid kernel, pcf x pcf, a define).
    static std::vector<glm::vec2> kernelOffsets(const PropertySet& p);
    /// Per light, the world size of a map texel at w = 1 (`texelWorld`), and `view`'s receivers and
    /// margins: how far each light's shadow may reach beyond a caster's bounds through the filter,
    /// `kernelTexels` + the normal offset + 2 texels at the farthest receiver.
    static void fitTexels(const Scene& scene, const FlatLightFits& lights, int mapSize, double kernelTexels,
                          float normalOffset, std::vector<float>& texelWorld, ViewCull& view);
    /// The counters of a frame, on both APIs: DepthLightingFrame's, the lights left unshadowed and the
    /// casters culled.
    static Counters counters(const SubmitStats& s, int mapSize, const FlatLightFits& lights, size_t culled);
};

} // namespace sb
