#include "techniques/raytraced/RayTraced.h"

#include <algorithm>
#include <string>
#include <vector>

#include "scenes/EmitterGrid.h"
#include "shading/GlslLiteral.h"
#include "techniques/Property.h"
#include "techniques/raytraced/GuidedRays.h"
#include "techniques/raytraced/LightEmitter.h"

namespace sb {

namespace {

constexpr RayTraced::ModeEntry kModes[] = {
    {RayTraced::Mode::Hard, "hard", "RT_MODE_HARD"},
    {RayTraced::Mode::Soft, "soft", "RT_MODE_SOFT"},
    {RayTraced::Mode::Guided, "guided", "RT_MODE_GUIDED"},
};
constexpr NameTable kModeNames{kModes};

std::vector<std::string> modeChoices() {
    std::vector<std::string> out;
    for (const RayTraced::ModeEntry& e : kModeNames.entries()) out.emplace_back(e.name);
    return out;
}

/// The knobs, one maker call each (techniques/Property.h): what --list shows and -t name:k=v sets.
std::vector<PropertyDesc> declareProperties() {
    std::vector<PropertyDesc> out = {
        choice(RayTraced::kMode, "hard", modeChoices(),
               "hard: one ray per fragment and light towards its centre (1 lit, 0 shadowed); soft: `rays` "
               "rays to stratified points of each area light's emitter, visibility the fraction unoccluded "
               "(the Embree reference's soft visibility); guided: hard's rays only where a depth map of the "
               "light is unsure"),
        integer(RayTraced::kRays, "16", 1, RayTraced::kMaxRays,
                "soft: rays per fragment and area light, rounded up to a square (side x side strata); a "
                "light without extent gets one"),
        flag(RayTraced::kTemporal, "false",
             "soft: a fresh jitter every frame and the visibility averaged over frames in a history image "
             "(exponential moving average; restarts when the camera or the scene moves)"),
    };
    for (PropertyDesc& d : GuidedRays::properties()) out.push_back(std::move(d));
    return out;
}

/// The modes the golden matrix judges beside hard (techniques/MatrixVariant.h), at their default knobs.
std::vector<MatrixVariant> matrixVariants() {
    return {
        {"mode=soft", AccuracyRule::Exact,
         "a light without extent (a point or a direction: every light of the built-in scenes, none of "
         "which has a \"shape\") gets the one ray mode=hard traces, so mode=soft's visibility there is "
         "hard's and is held to hard's rule; under an area light it is judged by its RMSE against the "
         "reference's soft visibility, as every technique is there"},
        {"mode=guided", AccuracyRule::Exact,
         "hard's ray wherever the light's depth map is unsure and the map's decision elsewhere, which can "
         "be wrong only at sub-texel features, contacts closer than `margin` texels and tight concave "
         "curves (techniques/raytraced/GuidedRays.h); measured when this rule was set, its image on every "
         "built-in scene equalled hard's (point lights have no map: all their rays are traced), so it is "
         "held to hard's exact rule rather than the shadow map's"},
    };
}

} // namespace

const NameTable<RayTraced::ModeEntry>& RayTraced::modes() {
    return kModeNames;
}

RayTraced::Mode RayTraced::mode(const PropertySet& properties) {
    // The property's choices are the table's names, so the value always parses.
    return *kModeNames.parse(properties.getEnum(kMode));
}

bool RayTraced::temporal(const PropertySet& properties) {
    return mode(properties) == Mode::Soft && properties.getBool(kTemporal);
}

int RayTraced::raySide(const PropertySet& properties) {
    return emitterGridSide(properties.getInt(kRays));
}

EffectMask RayTraced::effects(Mode mode) {
    const EffectMask hard =
        Effect::HardShadows | Effect::SelfShadowing | Effect::NonPlanarReceivers | Effect::MultipleLights;
    return mode == Mode::Soft ? hard | Effect::SoftShadows : hard;
}

TechniqueInfo RayTraced::declaration() {
    const char* hint = kDriverHint;
    return {
        .name = kName,
        .description =
            "ray-traced shadows: a ray per fragment and light from the lighting pass, or "
            "mode=soft stratified rays over each area light, or mode=guided rays only where a shadow map is "
            "unsure (Boksansky, Wimmer and Bittner, "
            "Ray Tracing Gems ch. 13; Vulkan ray queries)",
        .effects = effects(Mode::Hard),
        .capabilities = {{Api::Vulkan, "VK_KHR_acceleration_structure", 1, 2, "VK_KHR_acceleration_structure",
                          hint},
                         {Api::Vulkan, "VK_KHR_ray_query", 1, 2, "VK_KHR_ray_query", hint}},
        .passes = passes(Mode::Hard),
        .properties = declareProperties(),
        .quality = {},
        .resources = [](const PropertySet& p, const ResourceInputs& in) -> ResourceEstimate {
            if (mode(p) == Mode::Guided) return GuidedRays::resources(p, in);
            if (!temporal(p)) return {};
            const uint64_t pixels = uint64_t(std::max(0, in.width)) * uint64_t(std::max(0, in.height));
            return {pixels * kHistoryTexelBytes * kHistoryLayers,
                    std::to_string(in.width) + "x" + std::to_string(in.height) + " pixels x (" +
                        std::to_string(kHistoryTexelBytes) + " B x " + std::to_string(kHistoryLayers) +
                        " layers of history)"};
        },
        .matrixVariants = matrixVariants()};
}

std::vector<std::string> RayTraced::passes(Mode mode) {
    if (mode == Mode::Guided) return {"structures", "depth", "lighting"};
    return {"structures", "lighting"};
}

void RayTraced::addModeDefines(const PropertySet& properties, const Scene& scene, Defines& defines) {
    const Mode m = mode(properties);
    defines[kModeNames.find(m)->define] = "1";
    if (m != Mode::Soft) return;
    defines["RT_SIDE"] = std::to_string(raySide(properties));
    addEmitterDefines(scene, defines);
    if (!temporal(properties)) return;
    defines["RT_TEMPORAL"] = "1";
    defines["RT_HISTORY_WEIGHT"] = glslFloat(kHistoryWeight);
}

Counters RayTraced::counters(uint32_t structuresBuilt, uint64_t structureBytes, uint64_t raysTraced) {
    return {{"structures_built", double(structuresBuilt)},
            {"structure_bytes", double(structureBytes)},
            {"rays_traced", double(raysTraced)}};
}

Counters RayTraced::buildTimes(double bottomLevelsMs, double topLevelMs) {
    return {{"bottom_levels_build_ms", bottomLevelsMs}, {"top_level_build_ms", topLevelMs}};
}

} // namespace sb
