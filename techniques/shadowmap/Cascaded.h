#pragma once
// `cascaded`: cascaded shadow maps for directional lights (Engel 2006, Cascaded Shadow Maps, ShaderX5; Zhang
// et al. 2006, Parallel-Split Shadow Maps). The declaration (techniques/TechniqueInfo.h) its GL and Vulkan
// forms both take: name, effects, the capabilities of each API's form, passes, properties and quality knobs.
#include "techniques/TechniqueInfo.h"

namespace sb {

struct Cascaded {
    static constexpr const char* kBlend = "blend";
    static constexpr const char* kCascades = "cascades";
    static constexpr const char* kLambda = "lambda";
    static constexpr const char* kStabilize = "stabilize";

    /// The most cascades a light gets (the lighting shader's arrays).
    static constexpr int kMaxCascades = 4;

    static TechniqueInfo declaration();
};

} // namespace sb
