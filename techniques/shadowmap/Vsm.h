#pragma once
// `vsm`: variance shadow maps (Donnelly and Lauritzen 2006, Variance Shadow Maps, I3D).
// The declaration (techniques/TechniqueInfo.h) its GL and Vulkan forms both take: name, effects, the
// capabilities of each API's form, passes, properties and quality knobs.
#include "techniques/TechniqueInfo.h"

namespace sb {

struct Vsm {
    static constexpr const char* kBleedReduction = "bleed_reduction";
    static constexpr const char* kBlur = "blur";
    static constexpr const char* kCull = "cull";
    static constexpr const char* kMinVariance = "min_variance";
    static constexpr const char* kReceiverBackground = "receiver_background";
    static constexpr const char* kResolution = "resolution";

    static TechniqueInfo declaration();
};

} // namespace sb
