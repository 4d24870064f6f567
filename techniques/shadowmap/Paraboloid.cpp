#include "techniques/shadowmap/Paraboloid.h"

#include "techniques/Property.h"
#include "techniques/shadowmap/ShadowMapProperties.h"

namespace sb {

using P = ShadowMapProperties;

namespace {

std::vector<PropertyDesc> declareProperties() {
    return {
        P::resolution("2048",
                      "width and height of each paraboloid half and of each spot/directional map (texels)"),
        P::biasConstant(),
        P::biasSlope(),
        P::pcf("PCF kernel width: pcf x pcf taps one texel apart in map space"),
    };
}

} // namespace

TechniqueInfo Paraboloid::declaration() {
    return {.name = "paraboloid",
            .description = "dual-paraboloid shadow maps: two hemispherical depth maps per point light",
            .effects = Effect::HardShadows | Effect::SelfShadowing | Effect::NonPlanarReceivers |
                       Effect::MultipleLights,
            .capabilities = {{Api::GL, "GL 4.5", 4, 5, ""}},
            .passes = {"depth", "lighting"},
            .properties = declareProperties(),
            .quality = {
                {P::kResolution, {"512", "1024", "2048", "4096"}},
                P::pcfSweep(),
                P::biasConstantSweep(),
                P::biasSlopeSweep(),
            }};
}

} // namespace sb
