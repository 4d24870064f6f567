#pragma once
// `reference`: exact visibility ray-traced with Intel Embree, drawn as a technique; the ground truth.
// The declaration (techniques/TechniqueInfo.h) its GL and Vulkan forms both take: name, effects, the
// capabilities of each API's form, passes, properties and quality knobs.
#include "techniques/TechniqueInfo.h"

namespace sb {

struct Reference {
    static constexpr const char* kHard = "hard";
    static constexpr const char* kSamples = "samples";
    static constexpr const char* kThreads = "threads";

    static TechniqueInfo declaration();
};

} // namespace sb
