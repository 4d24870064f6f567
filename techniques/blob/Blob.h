#pragma once
// `blob`: fake blob shadows, a soft ellipse on the ground under each caster, after Crawfis, Ad-hoc shadows
// (CSE 781 slides). The declaration (techniques/TechniqueInfo.h) its GL and Vulkan forms both take: name,
// effects, the capabilities of each API's form, passes, properties and quality knobs.
#include "techniques/TechniqueInfo.h"

namespace sb {

struct Blob {
    static constexpr const char* kFade = "fade";
    static constexpr const char* kOpacity = "opacity";
    static constexpr const char* kSoftness = "softness";

    static TechniqueInfo declaration();
};

} // namespace sb
