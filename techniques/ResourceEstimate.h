#pragma once
// What a technique declares it allocates for one configuration (docs/USAGE.md, "--max-memory-gib"): its
// textures, buffers and CPU-side tables, from its properties, the frame size and the scene's lights,
// before anything is allocated. The run adds the scene's and the harness's own estimates and refuses a
// configuration above --max-memory-gib (registry/MemoryBudget.h). Memory the driver keeps for itself
// (compiled shaders, command streams, staging copies) is not counted.
#include <cstdint>
#include <functional>
#include <string>

#include "techniques/PropertySet.h"

namespace sb {

/// Bytes of one depth texel: DEPTH_COMPONENT24 (GL) and D32 (Vulkan) both take 4.
constexpr uint64_t kDepthTexelBytes = 4;

/// What an estimate may depend on besides the technique's properties.
struct ResourceInputs {
    int width = 0, height = 0; ///< the frame size (--size)
    int lights = 0;            ///< the scene's lights (every light gets its maps)
};

/// Bytes and how they were counted, for the refusal's line ("4096^2 texels x 4 B x 4 cascades x 1
/// light").
struct ResourceEstimate {
    uint64_t bytes = 0;
    std::string how;
};

/// A technique's declaration of its resources; empty: nothing that grows with its properties.
using ResourceDeclaration = std::function<ResourceEstimate(const PropertySet&, const ResourceInputs&)>;

/// Square maps: `resolution`^2 texels of `bytesPerTexel` each, `layers` of them per light (cascades,
/// cube faces, paraboloid halves), one set per light (at least one: a technique allocates its maps
/// whether or not the scene has lights). `extraPerTexel`: bytes per texel allocated once, not per
/// light (a blur's intermediate target, a depth buffer shared by the layers). Saturates, never wraps.
ResourceEstimate squareMaps(int64_t resolution, uint64_t bytesPerTexel, uint64_t layers,
                            const ResourceInputs& in, uint64_t extraPerTexel = 0);

} // namespace sb
