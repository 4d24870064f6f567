#include "techniques/blob/Blob.h"

#include "techniques/Property.h"

namespace sb {

namespace {

/// The knobs, one maker call each (techniques/Property.h): what --list shows and -t name:k=v sets.
std::vector<PropertyDesc> declareProperties() {
    return {
        real(Blob::kOpacity, "1", 0, 1, "opacity of a blob on the ground"),
        real(Blob::kSoftness, "0.5", 0, 1,
             "width of the soft edge as a fraction of the ellipse's radius (0: hard)"),
        real(Blob::kFade, "8", 0.01, 1e6,
             "height (in bounding radii) of the caster's bottom at which its blob vanishes"),
    };
}

} // namespace

TechniqueInfo Blob::declaration() {
    return {.name = "blob",
            .description = "fake blob shadows: a soft ellipse on the ground under each caster per light, "
                           "sized from its bounds (no self-shadowing, ground plane only)",
            .effects = Effect::SoftShadows | Effect::MultipleLights,
            .capabilities = {{Api::GL, "GL 4.5", 4, 5, ""}},
            .passes = {"lighting", "blobs"},
            .properties = declareProperties(),
            .quality = {
                {kSoftness, {"0", "0.25", "0.5", "1"}},
                {kFade, {"2", "8", "32"}},
            }};
}

} // namespace sb
