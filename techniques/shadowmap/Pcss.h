#pragma once
// `pcss`: percentage-closer soft shadows (Fernando 2005, Percentage-Closer Soft Shadows, SIGGRAPH sketch).
// The declaration (techniques/TechniqueInfo.h) its GL and Vulkan forms both take: name, effects, the
// capabilities of each API's form, passes, properties and quality knobs.
#include "techniques/TechniqueInfo.h"

namespace sb {

struct Pcss {
    static constexpr const char* kBlockerTaps = "blocker_taps";
    static constexpr const char* kFilterTaps = "filter_taps";
    static constexpr const char* kLightSize = "light_size";
    static constexpr int kMaxTaps = 64;

    static TechniqueInfo declaration();
};

} // namespace sb
