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
        flag(Paraboloid::kSplit, "true",
             "split the triangles of casters whose edges span more than the angle whose chord stays within "
             "half a texel of its arc, in a geometry stage of the depth pass (true), or project per vertex "
             "only, as the paper does (false: long edges bend, and shadow is lost at the halves' seam)"),
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
