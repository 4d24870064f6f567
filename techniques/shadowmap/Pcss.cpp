#include "techniques/shadowmap/Pcss.h"

#include "techniques/Property.h"
#include "techniques/shadowmap/ShadowMapProperties.h"

namespace sb {

using P = ShadowMapProperties;

namespace {

std::vector<PropertyDesc> declareProperties() {
    return {
        P::resolution("2048", "shadow map width and height (texels)"),
        integer(Pcss::kBlockerTaps, "16", 1, Pcss::kMaxTaps, "Poisson taps of the blocker search (step 1)"),
        integer(Pcss::kFilterTaps, "32", 1, Pcss::kMaxTaps,
                "Poisson taps of the PCF over the penumbra (step 3)"),
        real(Pcss::kLightSize, "0", 0, 1e6,
             "light size L (0 = the scene's emitter): diameter in world units for spot lights, width per "
             "unit depth (2 tan of the angular radius) for directional lights"),
        P::biasConstant("glPolygonOffset units of the depth pass"),
        P::biasSlope("glPolygonOffset factor of the depth pass"),
    };
}

} // namespace

TechniqueInfo Pcss::declaration() {
    return {.name = "pcss",
            .description = "percentage-closer soft shadows: blocker search, penumbra estimate, PCF over "
                           "it (a light with no extent gets a 1 degree emitter: counter "
                           "light_size_defaulted); penumbra width -5% to +9% of the closed form on thin "
                           "edges, +39% on a 1-thick box edge (techniques/shadowmap/README.md)",
            .effects = Effect::HardShadows | Effect::SoftShadows | Effect::SelfShadowing |
                       Effect::NonPlanarReceivers | Effect::MultipleLights,
            .capabilities = {{Api::GL, "GL 4.5", 4, 5, ""}},
            .passes = {"depth", "lighting"},
            .properties = declareProperties(),
            .quality = {
                {P::kResolution, {"512", "1024", "2048", "4096"}},
                {kBlockerTaps, {"4", "8", "16", "32"}},
                {kFilterTaps, {"8", "16", "32", "64"}},
                {kLightSize, {"0", "0.05", "0.2", "0.5"}},
            }};
}

} // namespace sb
