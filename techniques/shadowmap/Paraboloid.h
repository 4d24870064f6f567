#pragma once
// `paraboloid`: dual-paraboloid shadow maps for point lights (Brabec, Annen, Seidel 2002, Shadow Mapping for
// Hemispherical and Omnidirectional Light Sources). The declaration (techniques/TechniqueInfo.h) its GL and
// Vulkan forms both take: name, effects, the capabilities of each API's form, passes, properties and quality
// knobs.
#include <cstddef>

#include <glm/glm.hpp>

#include "shading/Defines.h"
#include "techniques/PropertySet.h"
#include "techniques/Submission.h"
#include "techniques/TechniqueInfo.h"
#include "techniques/shadowmap/OmniLightSet.h"

namespace sb {

struct Paraboloid {
    /// Property: split wide caster triangles in the depth pass (techniques/shadowmap/ParaboloidSplitting.h).
    static constexpr const char* kSplit = "split";
    static TechniqueInfo declaration();

    /// The axis of hemisphere `half` (0 front: -Y, 1 back: +Y), as shaders/shadowmap/paraboloid_frame.glsl
    /// sets it up.
    static glm::vec3 hemisphereAxis(int half);
    /// How far behind its plane each half's depth pass cuts the casters (the sine of the angle): the
    /// map keeps a ring of pcf / 2 + 2 texels outside the unit disc, filled with the other half's
    /// nearest edge, so that lookups at the light's height never filter in the cleared far depth.
    static float beyondRim(int resolution, int pcf);
    /// The lighting pass's defines on either API: `scene` (the submitter's and the scene's shadow
    /// exceptions) plus the maps `lights` has and the PCF width.
    static Defines lightingDefines(Defines scene, const PropertySet& p, const OmniLightSet& lights);
    /// The counters of a frame, on both APIs: DepthLightingFrame's over `layers` maps of `resolution`^2
    /// (every half and flat map), then hemispheres rendered, casters culled and split, lights skipped
    /// and unshadowed.
    static Counters counters(const SubmitStats& s, int resolution, int layers, const OmniLightSet& lights,
                             int hemispheresRendered, size_t culled, size_t split);
};

} // namespace sb
