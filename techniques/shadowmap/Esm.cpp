#include "techniques/shadowmap/Esm.h"

#include "techniques/ContactShadows.h"
#include "techniques/Property.h"

namespace sb {

namespace {

std::vector<PropertyDesc> declareProperties() {
    return MomentMapKind::properties(
        "depth map", ", over exp(c d)", {},
        {
            real(Esm::kExponent, "160", 1, Esm::kMaxExponent,
                 "c of exp(c (d_occ - t)) over linear depth in [0, 1]: larger is sharper towards contact"),
        });
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
