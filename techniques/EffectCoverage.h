#pragma once
// What a scene asks for against what a technique can produce (docs/ARCHITECTURE.md, "Effects"). The scene
// file's `effects` list is the request (scenes/SceneLoader.h); a technique's TechniqueInfo::effects is what
// it can deliver. Every result row carries the three masks (effects_requested, effects_delivered,
// effects_missing), a run prints one line for a technique that falls short, and `--strict-effects` turns
// that line into a refusal (exit 3). `bench explain` prints the same for a scene and technique.
#include <string>

#include "scenes/Scene.h"

namespace sb {

struct EffectCoverage {
    EffectMask requested = 0; ///< the scene's request
    EffectMask produced = 0;  ///< what the technique can deliver, requested or not
    EffectMask delivered = 0; ///< requested & produced
    EffectMask missing = 0;   ///< requested & ~produced

    static EffectCoverage of(EffectMask requested, EffectMask produced);

    /// A technique that declares no effect at all (`none`, `synthetic`) is a baseline: drawing no shadow
    /// is what it is for, so its missing effects are recorded in the row but never warned about or refused.
    bool baseline() const { return produced == 0; }
    /// Whether a run should say so (or, strict, refuse): something is missing and this is no baseline.
    bool fallsShort() const { return missing != 0 && !baseline(); }
    /// "planar cannot produce self_shadowing, which scene aircraft asks for", or "" when nothing is missing.
    std::string shortfall(const std::string& technique, const std::string& scene) const;
};

} // namespace sb
