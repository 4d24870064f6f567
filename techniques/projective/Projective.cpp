#include "techniques/projective/Projective.h"

#include "techniques/Property.h"

namespace sb {

namespace {

/// The knobs, one maker call each (techniques/Property.h): what --list shows and -t name:k=v sets.
std::vector<PropertyDesc> declareProperties() {
    return {
        integer(Projective::kResolution, "512", 16, 8192, "projective texture width and height (texels)"),
        integer(Projective::kBlur, "0", 0, 32, "blur radius in texels: the slides' fake softness"),
        flag(Projective::kCull, "true",
             "leave out of each light's texture the casters whose shadow cannot reach the view (blur 0 only: "
             "a blurred edge reaches further)"),
    };
}

} // namespace

TechniqueInfo Projective::declaration() {
    return {.name = "projective",
            .description = "projective texture shadows: casters black on white from each light, "
                           "projected onto the non-casting receivers (no self-shadowing)",
            // Blurred edges are a fixed-width fake, not soft shadows; casters are never shadowed.
            .effects = Effect::HardShadows | Effect::NonPlanarReceivers | Effect::MultipleLights,
            .capabilities = {{Api::GL, "GL 4.5", 4, 5, ""}},
            .passes = {"texture", "blur", "lighting"},
            .properties = declareProperties(),
            .quality = {
                {kResolution, {"128", "256", "512", "1024", "2048"}},
                {kBlur, {"0", "1", "2", "4", "8"}},
            }};
}

} // namespace sb
