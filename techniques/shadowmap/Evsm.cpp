#include "techniques/shadowmap/Evsm.h"

#include <cmath>

#include "shading/GlslLiteral.h"
#include "techniques/ContactShadows.h"
#include "techniques/Property.h"

namespace sb {

namespace {

std::vector<PropertyDesc> declareProperties() {
    return MomentMapKind::properties(
        "moment map", "",
        {
            choice(Evsm::kComponents, "4", {"2", "4"},
                   "2: the positive warp exp(c+ d) alone (RG32F); 4: with the negative warp -exp(-c- d) too "
                   "(RGBA32F), the lit fraction the smaller of the two bounds (Lauritzen and McCool 2008, "
                   "Layered Variance Shadow Maps, the section on the exponential warp)"),
            real(Evsm::kExponentPositive, "40", 1, Evsm::kMaxExponent,
                 "c+ of the positive warp exp(c+ d), d linear depth in [0, 1]: larger separates the depths "
                 "behind an occluder further (less light leaking); at most 42 so exp(2 c+) fits a float"),
            real(Evsm::kExponentNegative, "5", 1, Evsm::kMaxExponent,
                 "c- of the negative warp -exp(-c- d) (components=4 only): the paper's 32-bit pair is c+ = "
                 "40, c- = 5"),
        },
        {
            real(Evsm::kMinVariance, "1e-06", 0, 0.01,
                 "lower bound of the filtered variance on linear depth in [0, 1], squared, scaled into each "
                 "warped space by the warp's slope at the receiver, squared"),
            real(Evsm::kBleedReduction, "0.2", 0, 0.99,
                 "light-bleeding reduction as vsm's: linstep(amount, 1, p_max) on the smaller bound"),
        });
}

} // namespace

bool Evsm::negativeWarp(const PropertySet& p) {
    return p.getEnum(kComponents) == "4";
}

void Evsm::addDefines(const PropertySet& p, Defines& defines) {
    defines["EVSM_EXPONENTS"] =
        glslVec<2>(glm::vec2(float(p.getFloat(kExponentPositive)), float(p.getFloat(kExponentNegative))));
    if (negativeWarp(p)) defines["EVSM_NEGATIVE"] = "";
}

glm::vec4 Evsm::noOccluder(const PropertySet& p) {
    const float positive = std::exp(float(p.getFloat(kExponentPositive)));
    const float negative = -std::exp(-float(p.getFloat(kExponentNegative)));
    return {positive, positive * positive, negative, negative * negative};
}

TechniqueInfo Evsm::declaration() {
    return ContactShadows::declare(
        {.name = "evsm",
         .description = "exponential variance shadow maps: filtered moments of exponentially warped depth, "
                        "Chebyshev's bound per warp (Lauritzen and McCool 2008, Layered Variance Shadow "
                        "Maps, GI, the section on the exponential warp)",
         .effects = Effect::HardShadows | Effect::SelfShadowing | Effect::NonPlanarReceivers |
                    Effect::MultipleLights,
         .capabilities = {{Api::GL, "GL 4.5", 4, 5, ""}},
         .passes = {"depth", "blur", "lighting"},
         .properties = declareProperties(),
         .quality =
             {
                 {kResolution, {"256", "512", "1024", "2048", "4096"}},
                 {kBlur, {"0", "3", "5", "9"}},
                 {kComponents, {"2", "4"}},
                 {kExponentPositive, {"5", "20", "40"}},
             },
         .resources = [](const PropertySet& p, const ResourceInputs& in) {
             const uint64_t texel = uint64_t(channels(p)) * 4;
             return squareMaps(p.getInt(kResolution), texel, 1, in, texel + kDepthTexelBytes);
         }});
}

MomentMapKind Evsm::kind() {
    return {.declaration = &Evsm::declaration,
            .format =
                [](const PropertySet& p) {
                    return negativeWarp(p) ? MomentMapKind::Format::RGBA32F : MomentMapKind::Format::RG32F;
                },
            .depthDefines = &Evsm::addDefines,
            .lightingDefines = &Evsm::addDefines,
            .lightingFragment = "shadowmap/evsm.frag",
            .params = [](const PropertySet& p) -> std::vector<float> {
                return {float(p.getFloat(kMinVariance)), float(p.getFloat(kBleedReduction))};
            },
            .noOccluder = &Evsm::noOccluder,
            .logSpaceExponent = [](const PropertySet&) { return 0.0f; }};
}

} // namespace sb
