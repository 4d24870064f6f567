#pragma once
// `volume`: stencil shadow volumes after McGuire, Efficient Shadow Volume Rendering (GPU Gems ch. 9), every
// optimisation a property. The declaration (techniques/TechniqueInfo.h) its GL and Vulkan forms both take:
// name, effects, the capabilities of each API's form, passes, properties and quality knobs.
#include "techniques/TechniqueInfo.h"

namespace sb {

struct Volume {
    static TechniqueInfo declaration();
};

} // namespace sb
