#pragma once
// What the command line can change about a scene after it is loaded (bench --instances, --scale ...).
#include <cstdint>
#include <optional>
#include <string>

#include "scenes/Scene.h"

namespace sb {

struct SceneOptions {
    std::optional<uint32_t> instances; ///< overrides the layout's count (--instances N)
    float scale = 1.0f;                ///< multiplies the scale of every layout instance (--scale S)
    std::optional<uint32_t> seed;      ///< overrides the layout's seed (--seed N)
    std::optional<int> tessellation;   ///< overrides every generator's tessellation knob (--tess N)
    /// Multiplies every generator's tessellation (after --tess), rounded, at least the generator's
    /// minimum (--tess-factor F): the bottleneck study's vertex-load knob, which keeps each mesh's own
    /// proportions where one --tess N would not.
    float tessellationFactor = 1.0f;
    std::optional<LightType> lightType;   ///< replaces the type of every light (--light TYPE)
    std::optional<LightingRate> lighting; ///< replaces the scene's "lighting" (--lighting RATE)
    std::string modelPath;                ///< replaces the layout mesh with a model file (--model PATH)
    /// Refuse scenes whose estimated GPU+CPU memory exceeds this many bytes (absurd --instances).
    uint64_t memoryLimitBytes = 8ull << 30;
};

} // namespace sb
