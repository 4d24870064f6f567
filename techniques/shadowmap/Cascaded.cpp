#include "techniques/shadowmap/Cascaded.h"

#include <string>

#include "techniques/ContactShadows.h"
#include "techniques/Property.h"
#include "techniques/ShadowMapProperties.h"
#include "techniques/ViewDepth.h"

namespace sb {

using P = ShadowMapProperties;

namespace {

/// The knobs, one maker call each (techniques/Property.h): what --list shows and -t name:k=v sets.
std::vector<PropertyDesc> declareProperties() {
    std::vector<PropertyDesc> out = {
        P::resolution("2048", "width and height of each cascade's map (texels)"),
        integer(Cascaded::kCascades, "4", 1, Cascaded::kMaxCascades,
                "slices of the view frustum, one map each (directional lights)"),
        choice(Cascaded::kFit, Cascaded::kFitPractical, {Cascaded::kFitPractical, Cascaded::kFitSdsm},
               "where the splits go: practical (Zhang et al. 2006, weighted by lambda, over the receivers' "
               "depths) or sdsm (Lauritzen, Salvi and Lefohn 2011, Sample Distribution Shadow Maps: the "
               "logarithmic split of the min and max view depth a depth pre-pass finds, reduced on the GPU)"),
        real(Cascaded::kLambda, "0.75", 0, 1,
             "practical split weight: 0 uniform, 1 logarithmic (Zhang et al. 2006); fit=sdsm ignores it"),
        flag(Cascaded::kStabilize, "true",
             "bounding-sphere extent snapped to whole texels (no shimmer) instead of the tight box"),
        real(Cascaded::kBlend, "0.1", 0, 1,
             "fraction of each cascade, at its far end, blended into the next"),
        P::biasConstant(),
        P::biasSlope(),
        P::pcf("PCF kernel width: pcf x pcf hardware-compare taps one texel apart"),
    };
    const std::vector<PropertyDesc> contact = ContactShadows::properties();
    out.insert(out.end(), contact.begin(), contact.end());
    return out;
}

} // namespace

TechniqueInfo Cascaded::declaration() {
    return {.name = "cascaded",
            .description = "cascaded shadow maps: the view frustum split into slices (practical split, or "
                           "fit=sdsm: Lauritzen, Salvi and Lefohn 2011, Sample Distribution Shadow Maps, its "
                           "z-partitioning of the view's own min and max depth), one stable map per slice",
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
            .resources =
                [](const PropertySet& p, const ResourceInputs& in) {
                    ResourceEstimate e = squareMaps(p.getInt(P::kResolution), kDepthTexelBytes,
                                                    uint64_t(p.getInt(kCascades)), in);
                    if (!sampleDistribution(p)) return e;
                    // fit=sdsm's view depth pre-pass (its two 8-byte answer buffers are below the estimate's
                    // resolution).
                    e.bytes += ViewDepth::bytes(in.width, in.height);
                    e.how += " + " + ViewDepth::describe(in.width, in.height, "fit=sdsm");
                    return e;
                },
            .matrixVariants = {{std::string(kFit) + "=" + kFitSdsm, AccuracyRule::Map,
                                "the same cascades, maps, filter and bias as fit=practical, only their "
                                "splits fitted to the view's own depth range: a shadow map, held to the "
                                "shadow map's rule"}}};
}

bool Cascaded::sampleDistribution(const PropertySet& p) {
    return p.getEnum(kFit) == kFitSdsm;
}

bool Cascaded::viewDepth(const PropertySet& p) {
    return sampleDistribution(p) || ContactShadows::enabled(p);
}

const char* Cascaded::viewDepthPass(const PropertySet& p) {
    return sampleDistribution(p) ? "depth_range" : ContactShadows::kPass;
}

std::vector<std::string> Cascaded::passes(const PropertySet& p) {
    if (!viewDepth(p)) return {"depth", "lighting"};
    return {viewDepthPass(p), "depth", "lighting"};
}

} // namespace sb
