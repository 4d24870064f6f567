#include "reference/Reference.h"

#include "techniques/Property.h"

namespace sb {

namespace {

/// The knobs, one maker call each (techniques/Property.h): what --list shows and -t name:k=v sets.
std::vector<PropertyDesc> declareProperties() {
    return {
        integer(Reference::kSamples, "64", 1, 4096, "area-light samples per pixel (stratified)"),
        integer(Reference::kThreads, "0", 0, 256, "tracing threads, 0 = all"),
        flag(Reference::kHard, "false", "treat area lights as points"),
    };
}

} // namespace

TechniqueInfo Reference::declaration() {
    return {.name = "reference",
            .description = "exact visibility by ray tracing (Intel Embree): the ground truth",
            .effects = Effect::HardShadows | Effect::SoftShadows | Effect::SelfShadowing |
                       Effect::NonPlanarReceivers | Effect::MultipleLights,
            .capabilities = {{Api::GL, "GL 4.5", 4, 5, ""}},
            .passes = {"gbuffer", "trace", "shade"},
            .properties = declareProperties()};
}

} // namespace sb
