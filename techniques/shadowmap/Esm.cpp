#include "techniques/shadowmap/Esm.h"

#include "techniques/ContactShadows.h"
#include "techniques/LightFitProperties.h"
#include "techniques/Property.h"
#include "techniques/ShadowMapProperties.h"

namespace sb {

namespace {

std::vector<PropertyDesc> declareProperties() {
    return {
        integer(Esm::kResolution, "1024", 16, 8192, "depth map width and height (texels)"),
        integer(
            Esm::kBlur, "3", 0, ShadowMapProperties::kMaxBlurWidth,
            "separable Gaussian kernel width in texels, over exp(c d) (sigma = width / 4; 0 or 1 = no blur)"),
        flag(Esm::kReceiverBackground, "true",
             "non-casters drawn behind the casters as the map's background (the farthest per texel): the "
             "filter sees the receiver, not the far plane, beside an occluder's edge"),
        flag(Esm::kCull, "true",
             "leave out of each light's map the casters whose shadow cannot reach the view (grown by the "
             "blur's reach)"),
        real(Esm::kExponent, "160", 1, Esm::kMaxExponent,
             "c of exp(c (d_occ - t)) over linear depth in [0, 1]: larger is sharper towards contact"),
        LightFitProperties::fit("map", "spot lights take their cone"),
        LightFitProperties::fitMargin(),
    };
}

} // namespace

TechniqueInfo Esm::declaration() {
    return ContactShadows::declare(
        {.name = "esm",
         .description = "exponential shadow maps: filtered exp(c d), filtered in log space",
         .effects = Effect::HardShadows | Effect::SelfShadowing | Effect::NonPlanarReceivers |
                    Effect::MultipleLights,
         .capabilities = {{Api::GL, "GL 4.5", 4, 5, ""}},
         .passes = {"depth", "blur", "lighting"},
         .properties = declareProperties(),
         .quality =
             {
                 {kResolution, {"256", "512", "1024", "2048", "4096"}},
                 {kBlur, {"0", "3", "5", "9"}},
                 {kExponent, {"10", "40", "80", "160", "500"}},
             },
         .resources = [](const PropertySet& p, const ResourceInputs& in) {
             return squareMaps(p.getInt(kResolution), 4, 1, in, 4 + kDepthTexelBytes);
         }});
}

MomentMapKind Esm::kind() {
    return {
        .declaration = &Esm::declaration,
        .format = [](const PropertySet&) { return MomentMapKind::Format::R32F; },
        .depthDefines = [](const PropertySet&, Defines&) {},
        .lightingDefines = [](const PropertySet&, Defines&) {},
        .lightingFragment = "shadowmap/esm.frag",
        .params = [](const PropertySet& p) -> std::vector<float> { return {float(p.getFloat(kExponent))}; },
        // d = 1.
        .noOccluder = [](const PropertySet&) { return glm::vec4(1.0f, 0.0f, 0.0f, 0.0f); },
        .logSpaceExponent = [](const PropertySet& p) { return float(p.getFloat(kExponent)); }};
}

} // namespace sb
