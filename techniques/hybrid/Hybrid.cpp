#include "techniques/hybrid/Hybrid.h"

#include "techniques/Property.h"

namespace sb {

TechniqueInfo Hybrid::declaration(const std::vector<std::string>& choices) {
    return {
        .name = "hybrid",
        .description = "two techniques in one frame: one shades the casters (self-shadowing), the "
                       "other the ground (cast shadows)",
        .effects = 0,
        .capabilities = {},
        .passes = {},
        .properties =
            {
                choice(kSelf, "occluder", choices,
                       "the technique that shades the instances that cast a shadow (their self-shadowing)"),
                choice(kCast, "shadowmap", choices,
                       "the technique that shades the instances that cast none (where cast shadows fall)"),
            },
        .quality = {}};
}

EffectMask Hybrid::combinedEffects(EffectMask self, EffectMask cast) {
    const EffectMask selfShadowing = uint32_t(Effect::SelfShadowing);
    return (self & cast & ~selfShadowing) | (self & selfShadowing);
}

} // namespace sb
