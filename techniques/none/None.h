#pragma once
// `none`: lit, unshadowed, one pass; the baseline every overhead ratio is taken against.
// The declaration (techniques/TechniqueInfo.h) its GL and Vulkan forms both take: name, effects, the
// capabilities of each API's form, passes, properties and quality knobs.
#include "techniques/TechniqueInfo.h"

namespace sb {

struct None {
    static TechniqueInfo declaration();
};

} // namespace sb
