#pragma once
// `cubemap`: omnidirectional shadow mapping with a depth cube map per point light (Gerasimov 2004,
// Omnidirectional Shadow Mapping, GPU Gems ch. 12). The declaration (techniques/TechniqueInfo.h) its GL and
// Vulkan forms both take: name, effects, the capabilities of each API's form, passes, properties and quality
// knobs.
#include <vector>

#include "shading/Defines.h"
#include "techniques/PropertySet.h"
#include "techniques/Submission.h"
#include "techniques/TechniqueInfo.h"
#include "techniques/shadowmap/CubeFaces.h"
#include "techniques/shadowmap/OmniLightSet.h"

namespace sb {

struct CubeMap {
    static constexpr const char* kLayered = "layered";

    static TechniqueInfo declaration();
    /// A point light with a cube map: its fit and the six faces' cameras.
    struct Cube {
        PointLightFit light;
        CubeFaces faces;
    };
    /// The cubes of `lights`' point lights that have a map, in cube order (both APIs' setScene).
    static std::vector<Cube> cubes(const OmniLightSet& lights);
    /// The lighting pass's defines on either API: `scene` (the submitter's and the scene's shadow
    /// exceptions) plus the maps `lights` has and the PCF width.
    static Defines lightingDefines(Defines scene, const PropertySet& p, const OmniLightSet& lights);
    /// The counters of a frame, on both APIs: DepthLightingFrame's over every face and flat map of
    /// `lights` at `resolution`, then faces rendered, casters culled, lights skipped and unshadowed.
    static Counters counters(const SubmitStats& s, int resolution, const OmniLightSet& lights,
                             size_t facesRendered, size_t culled);
};

} // namespace sb
