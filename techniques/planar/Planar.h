#pragma once
// `planar`: projected planar shadows, after Crawfis, Ad-hoc shadows (CSE 781 slides).
// The declaration (techniques/TechniqueInfo.h) its GL and Vulkan forms both take: name, effects, the
// capabilities of each API's form, passes, properties and quality knobs.
#include "techniques/TechniqueInfo.h"

namespace sb {

struct Planar {
    static constexpr const char* kCull = "cull";
    static constexpr const char* kDarkness = "darkness";
    static constexpr const char* kGuards = "guards";
    static constexpr const char* kOccluder = "occluder";
    static constexpr const char* kStencil = "stencil";

    static TechniqueInfo declaration();
};

} // namespace sb
