#pragma once
// `synthetic`: workloads of known bottleneck that validate the bottleneck classifier.
// The declaration (techniques/TechniqueInfo.h) its GL and Vulkan forms both take: name, effects, the
// capabilities of each API's form, passes, properties and quality knobs.
#include "techniques/TechniqueInfo.h"

namespace sb {

struct Synthetic {
    static constexpr const char* kDrawScene = "draw_scene";
    static constexpr const char* kFragmentIterations = "fragment_iterations";
    static constexpr const char* kVertexIterations = "vertex_iterations";

    static TechniqueInfo declaration();
};

} // namespace sb
