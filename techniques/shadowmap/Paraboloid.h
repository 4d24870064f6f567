#pragma once
// `paraboloid`: dual-paraboloid shadow maps for point lights (Brabec, Annen, Seidel 2002, Shadow Mapping for
// Hemispherical and Omnidirectional Light Sources). The declaration (techniques/TechniqueInfo.h) its GL and
// Vulkan forms both take: name, effects, the capabilities of each API's form, passes, properties and quality
// knobs.
#include "techniques/TechniqueInfo.h"

namespace sb {

struct Paraboloid {
    /// Property: split wide caster triangles in the depth pass (techniques/shadowmap/ParaboloidSplitting.h).
    static constexpr const char* kSplit = "split";
    static TechniqueInfo declaration();
};

} // namespace sb
