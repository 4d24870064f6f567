#include "techniques/raytraced/RayTraced.h"

#include <vector>

#include "techniques/Property.h"

namespace sb {

namespace {

constexpr RayTraced::ModeEntry kModes[] = {
    {RayTraced::Mode::Hard, "hard", "RT_MODE_HARD"},
};
constexpr NameTable kModeNames{kModes};

std::vector<std::string> modeChoices() {
    std::vector<std::string> out;
    for (const RayTraced::ModeEntry& e : kModeNames.entries()) out.emplace_back(e.name);
    return out;
}

/// The knobs, one maker call each (techniques/Property.h): what --list shows and -t name:k=v sets.
std::vector<PropertyDesc> declareProperties() {
    return {
        choice(RayTraced::kMode, "hard", modeChoices(),
               "hard: one ray per fragment and light towards its centre (1 lit, 0 shadowed)"),
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

TechniqueInfo RayTraced::declaration() {
    const char* hint = kDriverHint;
    return {.name = kName,
            .description = "ray-traced shadows: a ray per fragment and light from the lighting pass "
                           "(Boksansky, Wimmer and Bittner, Ray Tracing Gems ch. 13; Vulkan ray queries)",
            .effects = Effect::HardShadows | Effect::SelfShadowing | Effect::NonPlanarReceivers |
                       Effect::MultipleLights,
            .capabilities = {{Api::Vulkan, "VK_KHR_acceleration_structure", 1, 2,
                              "VK_KHR_acceleration_structure", hint},
                             {Api::Vulkan, "VK_KHR_ray_query", 1, 2, "VK_KHR_ray_query", hint}},
            .passes = {"structures", "lighting"},
            .properties = declareProperties(),
            .quality = {}};
}

void RayTraced::addModeDefines(Mode mode, Defines& defines) {
    defines[kModeNames.find(mode)->define] = "1";
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
