#include "techniques/shadowmap/Vsm.h"

#include "techniques/ContactShadows.h"
#include "techniques/Property.h"

namespace sb {

namespace {

std::vector<PropertyDesc> declareProperties() {
    return MomentMapKind::properties(
        "moment map", "", {},
        {
            real(Vsm::kMinVariance, "1e-06", 0, 0.01,
                 "lower bound of the filtered variance (linear depth in [0, 1], squared): against the "
                 "bound's numeric acne"),
            real(Vsm::kBleedReduction, "0.2", 0, 0.99,
                 "light-bleeding reduction: linstep(amount, 1, p_max) removes the bound's [0, amount] tail; "
                 "it trades light leaks for darkened soft edges: two plates overlapping in the map leak "
                 "0.78% of pixels at 0 and 0.2, 0 at 0.5; a plate 0.3 above the ground 4.7% at 0, 4.2% at "
                 "0.2, 2.9% at 0.5, 0 only at 0.9; aircraft's false shadow 0.25% at 0.2, 0.58% at 0.5 "
                 "(techniques/shadowmap/README.md)"),
        });
}

} // namespace

TechniqueInfo Vsm::declaration() {
    return ContactShadows::declare(
        {.name = "vsm",
         .description = "variance shadow maps: filtered moments, Chebyshev's bound in the lighting pass",
         .effects = Effect::HardShadows | Effect::SelfShadowing | Effect::NonPlanarReceivers |
                    Effect::MultipleLights,
         .capabilities = {{Api::GL, "GL 4.5", 4, 5, ""}},
         .passes = {"depth", "blur", "lighting"},
         .properties = declareProperties(),
         .quality =
             {
                 {kResolution, {"256", "512", "1024", "2048", "4096"}},
                 {kBlur, {"0", "3", "5", "9"}},
                 {kBleedReduction, {"0", "0.2", "0.4", "0.6"}},
             },
         .resources = [](const PropertySet& p, const ResourceInputs& in) {
             return squareMaps(p.getInt(kResolution), 8, 1, in, 8 + kDepthTexelBytes);
         }});
}

MomentMapKind Vsm::kind() {
    return {.declaration = &Vsm::declaration,
            .format = [](const PropertySet&) { return MomentMapKind::Format::RG32F; },
            .depthDefines = [](const PropertySet&, Defines& d) { d["VSM"] = ""; },
            .lightingDefines = [](const PropertySet&, Defines&) {},
            .lightingFragment = "shadowmap/vsm.frag",
            .params = [](const PropertySet& p) -> std::vector<float> {
                return {float(p.getFloat(kMinVariance)), float(p.getFloat(kBleedReduction))};
            },
            // The moments of d = 1.
            .noOccluder = [](const PropertySet&) { return glm::vec4(1.0f, 1.0f, 0.0f, 0.0f); },
            .logSpaceExponent = [](const PropertySet&) { return 0.0f; }};
}

} // namespace sb
