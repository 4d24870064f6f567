#include "techniques/planar/Planar.h"

#include "techniques/Property.h"

namespace sb {

namespace {

/// The knobs, one maker call each (techniques/Property.h): what --list shows and -t name:k=v sets.
std::vector<PropertyDesc> declareProperties() {
    return {
        flag(Planar::kStencil, "true",
             "the slides' stencil algorithm (false: depth-tested with bias: double blending, shadows off the "
             "receiver)"),
        choice(Planar::kOccluder, "mesh", {"mesh", "proxy"},
               "what is flattened: the caster's mesh, or its ShadowProxy (sphere/box/cylinder)"),
        real(Planar::kDarkness, "1", 0, 1,
             "share of the light a shadow removes (1: ambient only, like the other techniques)"),
        flag(Planar::kGuards, "true",
             "clip occluder parts behind the receiver or beyond the light, skip lights behind the plane "
             "(false: the slides' wrong shadows and anti-shadows)"),
        flag(Planar::kCull, "true",
             "leave out of a flattening the casters whose flattened bounds miss the view (mesh occluders; "
             "a flattening none reaches is skipped, its receiver marking too)"),
    };
}

} // namespace

TechniqueInfo Planar::declaration() {
    return {.name = "planar",
            .description = "projected planar shadows: casters flattened onto each receiver plane, stencil "
                           "keeps them on it (no self-shadowing, planar receivers only)",
            .effects = Effect::HardShadows | Effect::MultipleLights,
            .capabilities = {{Api::GL, "GL 4.5", 4, 5, ""}},
            .passes = {"lighting", "shadows"},
            .properties = declareProperties(),
            .quality = {
                {kOccluder, {"mesh", "proxy"}},
                {kStencil, {"true", "false"}},
            }};
}

} // namespace sb
