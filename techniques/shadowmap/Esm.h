#pragma once
// `esm`: exponential shadow maps (Annen et al. 2008, Exponential Shadow Maps, GI).
// The declaration (techniques/TechniqueInfo.h) its GL and Vulkan forms both take: name, effects, the
// capabilities of each API's form, passes, properties and quality knobs.
#include "techniques/TechniqueInfo.h"

namespace sb {

struct Esm {
    static constexpr const char* kBlur = "blur";
    static constexpr const char* kCull = "cull";
    static constexpr const char* kExponent = "exponent";
    static constexpr const char* kReceiverBackground = "receiver_background";
    static constexpr const char* kResolution = "resolution";

    /// The largest `exponent`: exp(c) of a depth difference of 1 is far outside float range; the log-space
    /// filter never forms it.
    static constexpr double kMaxExponent = 500.0;

    static TechniqueInfo declaration();
};

} // namespace sb
