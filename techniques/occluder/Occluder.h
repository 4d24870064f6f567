#pragma once
// `occluder`: single-pass self-shadowing from shadow planes with occluder textures, after Coleman, Fast
// Self-Shadowing Using Occluder Textures (MSc thesis). The declaration (techniques/TechniqueInfo.h) its GL
// and Vulkan forms both take: name, effects, the capabilities of each API's form, passes, properties and
// quality knobs.
#include "techniques/TechniqueInfo.h"

namespace sb {

struct Occluder {
    static constexpr const char* kDilate = "dilate";
    static constexpr const char* kLightSpace = "light_space";
    static constexpr const char* kPlanes = "planes";
    static constexpr const char* kReceivers = "receivers";
    static constexpr const char* kResolution = "resolution";

    /// Most planes per mesh the vertex stage passes on (varying budget: 16 planes x 1 light).
    static constexpr int kMaxPlanes = 16;

    static TechniqueInfo declaration();
};

} // namespace sb
