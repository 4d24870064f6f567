#pragma once
// `hybrid`: two techniques in one frame, one per role (Coleman's conclusion: occluder textures for the
// casters, a shadow map, planar or projective shadows for the ground). The declaration its forms take:
// the properties naming the parts, and the rule by which the parts' effects combine; the passes and
// capabilities follow from the parts (HybridGL::propertiesApplied).
#include <string>
#include <utility>
#include <vector>

#include "core/Error.h"
#include "scenes/Scene.h"
#include "techniques/TechniqueInfo.h"

namespace sb {

struct Hybrid {
    static constexpr const char* kSelf = "self";
    static constexpr const char* kCast = "cast";

    /// The declaration with `choices` (the techniques a part may be) for both roles.
    static TechniqueInfo declaration(const std::vector<std::string>& choices);
    /// What a hybrid delivers: self-shadowing from the self part; every other effect needs both parts.
    static EffectMask combinedEffects(EffectMask self, EffectMask cast);

    // What both forms share (techniques/hybrid/HybridPart.h uses these).
    /// The instances a role shades: the casters for self, the others for cast.
    static bool inRole(const std::string& role, const Instance& inst);
    /// Why a role whose scope is empty on the scene runs no pass.
    static const char* emptyRoleReason(const std::string& role);
    /// "<role>_<pass>", interned: it lives as long as the process (pass timers keep names by pointer).
    static const char* passName(const std::string& role, const std::string& pass);
    /// A part's error named after its role: "shadowmap: light 0 is ..." -> "hybrid: the cast part
    /// (shadowmap): light 0 is ...", with the same exit code.
    static Error partError(const std::string& role, const std::string& technique, const Error& e);
    /// Appends each program key of `key` ('|'-joined) as "<role>:<program>" to `keys`.
    static void appendRoleKeys(const std::string& role, const std::string& key,
                               std::vector<std::string>& keys);
    static std::string joinKeys(const std::vector<std::string>& keys);
    /// Each role's counters as "<role>_<name>", after draw_calls and triangles summed over the roles.
    static Counters combinedCounters(const std::vector<std::pair<std::string, Counters>>& byRole);
};

} // namespace sb
