#include "techniques/shadowmap/Msm.h"

#include "techniques/ContactShadows.h"
#include "techniques/Property.h"

namespace sb {

namespace {

std::vector<PropertyDesc> declareProperties() {
    return MomentMapKind::properties(
        "moment map", "",
        {
            choice(Msm::kFormat, "unorm16", {"unorm16", "float"},
                   "unorm16: the four moments through the paper's quantisation transform into RGBA16 unorm, "
                   "64 bits per texel (Peters and Klein 2015, Moment Shadow Mapping, the section on "
                   "quantization); float: the raw moments in RGBA32F, 128 bits"),
            real(Msm::kMomentBias, "3e-05", 0, 0.01,
                 "alpha of the moment bias b' = (1 - alpha) b + alpha (0.5, 0.5, 0.5, 0.5) before the "
                 "Hamburger reconstruction (the paper's value for the 64-bit map): keeps the moments' Hankel "
                 "matrix positive definite after filtering and rounding"),
        },
        {
            real(Msm::kBleedReduction, "0", 0, 0.99,
                 "light-bleeding reduction as vsm's, linstep(amount, 1, visibility); 0: the four moments' "
                 "bound is tight for two depths, where vsm's leaks"),
        });
}

} // namespace

bool Msm::quantized(const PropertySet& p) {
    return p.getEnum(kFormat) == "unorm16";
}

void Msm::addDefines(const PropertySet& p, Defines& defines) {
    defines["MSM"] = "";
    if (quantized(p)) defines["MSM_QUANTIZED"] = "";
}

glm::vec4 Msm::noOccluder(const PropertySet& p) {
    if (!quantized(p)) return glm::vec4(1.0f);
    // msmQuantize(msmMoments(1)) = (sum of the transform's rows) + offset.
    return {0.9999999892f, 0.9975599302f, 0.8934375093f, 3.0e-10f};
}

TechniqueInfo Msm::declaration() {
    return ContactShadows::declare(
        {.name = "msm",
         .description = "moment shadow maps: four filtered moments of depth, the Hamburger reconstruction "
                        "in the lighting pass (Peters and Klein 2015, Moment Shadow Mapping, I3D)",
         .effects = Effect::HardShadows | Effect::SelfShadowing | Effect::NonPlanarReceivers |
                    Effect::MultipleLights,
         .capabilities = {{Api::GL, "GL 4.5", 4, 5, ""}},
         .passes = {"depth", "blur", "lighting"},
         .properties = declareProperties(),
         .quality =
             {
                 {kResolution, {"256", "512", "1024", "2048", "4096"}},
                 {kBlur, {"0", "3", "5", "9"}},
                 {kFormat, {"unorm16", "float"}},
             },
         .resources = [](const PropertySet& p, const ResourceInputs& in) {
             const uint64_t texel = uint64_t(texelBytes(p));
             return squareMaps(p.getInt(kResolution), texel, 1, in, texel + kDepthTexelBytes);
         }});
}

MomentMapKind Msm::kind() {
    return {.declaration = &Msm::declaration,
            .format =
                [](const PropertySet& p) {
                    return quantized(p) ? MomentMapKind::Format::RGBA16Unorm : MomentMapKind::Format::RGBA32F;
                },
            .depthDefines = &Msm::addDefines,
            .lightingDefines = &Msm::addDefines,
            .lightingFragment = "shadowmap/msm.frag",
            .params = [](const PropertySet& p) -> std::vector<float> {
                return {float(p.getFloat(kMomentBias)), float(p.getFloat(kBleedReduction))};
            },
            .noOccluder = &Msm::noOccluder,
            .logSpaceExponent = [](const PropertySet&) { return 0.0f; }};
}

} // namespace sb
