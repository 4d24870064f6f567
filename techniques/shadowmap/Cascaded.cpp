#include "techniques/shadowmap/Cascaded.h"

#include "techniques/Property.h"
#include "techniques/ShadowMapProperties.h"

namespace sb {

using P = ShadowMapProperties;

namespace {

/// The knobs, one maker call each (techniques/Property.h): what --list shows and -t name:k=v sets.
std::vector<PropertyDesc> declareProperties() {
    return {
        P::resolution("2048", "width and height of each cascade's map (texels)"),
        integer(Cascaded::kCascades, "4", 1, Cascaded::kMaxCascades,
                "slices of the view frustum, one map each (directional lights)"),
        real(Cascaded::kLambda, "0.75", 0, 1,
             "practical split weight: 0 uniform, 1 logarithmic (Zhang et al. 2006)"),
        flag(Cascaded::kStabilize, "true",
             "bounding-sphere extent snapped to whole texels (no shimmer) instead of the tight box"),
        real(Cascaded::kBlend, "0.1", 0, 1,
             "fraction of each cascade, at its far end, blended into the next"),
        P::biasConstant(),
        P::biasSlope(),
        P::pcf("PCF kernel width: pcf x pcf hardware-compare taps one texel apart"),
    };
}

} // namespace

TechniqueInfo Cascaded::declaration() {
    return {.name = "cascaded",
            .description = "cascaded shadow maps: the view frustum split into slices (practical split), "
                           "one stable map per slice",
            .effects = Effect::HardShadows | Effect::SelfShadowing | Effect::NonPlanarReceivers |
                       Effect::MultipleLights,
            .capabilities = {{Api::GL, "GL 4.5", 4, 5, ""}},
            .passes = {"depth", "lighting"},
            .properties = declareProperties(),
            // What `bench accuracy --sweep` walks, one knob at a time around the defaults.
            .quality =
                {
                    {P::kResolution, {"256", "512", "1024", "2048", "4096"}},
                    {kCascades, {"1", "2", "3", "4"}},
                    {kLambda, {"0", "0.25", "0.5", "0.75", "1"}},
                    P::pcfSweep(),
                },
            .resources = [](const PropertySet& p, const ResourceInputs& in) {
                return squareMaps(p.getInt(P::kResolution), kDepthTexelBytes, uint64_t(p.getInt(kCascades)),
                                  in);
            }};
}

} // namespace sb
