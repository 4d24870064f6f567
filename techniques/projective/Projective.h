#pragma once
// `projective`: projective texture shadows, after Crawfis, Ad-hoc shadows (CSE 781 slides).
// The declaration (techniques/TechniqueInfo.h) its GL and Vulkan forms both take: name, effects, the
// capabilities of each API's form, passes, properties and quality knobs.
#include "techniques/TechniqueInfo.h"

namespace sb {

struct Projective {
    static constexpr const char* kBlur = "blur";
    static constexpr const char* kCull = "cull";
    static constexpr const char* kResolution = "resolution";

    static TechniqueInfo declaration();
};

} // namespace sb
