#pragma once
// `hybrid`: two techniques in one frame, one per role (Coleman's conclusion: occluder textures for the
// casters, a shadow map, planar or projective shadows for the ground). The declaration its forms take:
// the properties naming the parts, and the rule by which the parts' effects combine; the passes and
// capabilities follow from the parts (HybridGL::propertiesApplied).
#include <string>
#include <vector>

#include "techniques/TechniqueInfo.h"

namespace sb {

struct Hybrid {
    static constexpr const char* kSelf = "self";
    static constexpr const char* kCast = "cast";

    /// The declaration with `choices` (the techniques a part may be) for both roles.
    static TechniqueInfo declaration(const std::vector<std::string>& choices);
    /// What a hybrid delivers: self-shadowing from the self part; every other effect needs both parts.
    static EffectMask combinedEffects(EffectMask self, EffectMask cast);
};

} // namespace sb
