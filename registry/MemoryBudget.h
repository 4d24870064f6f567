#pragma once
// The memory limit (--max-memory-gib, SceneOptions::memoryLimitBytes) over a whole configuration: the
// scene's estimate (scenes/SceneLoader.h), the harness's frame targets and what the technique declares
// it allocates (techniques/ResourceEstimate.h), checked before any of it is allocated. A configuration
// over the limit is bad input (exit 2), refused with one line naming the technique, its properties and
// the estimate, as the scene's own estimate is refused. Memory the driver keeps for itself (compiled
// shaders, command streams, staging copies) is not counted.
#include <cstdint>
#include <string>
#include <vector>

#include "techniques/PropertySet.h"
#include "techniques/ResourceEstimate.h"

namespace sb {

class MemoryBudget {
public:
    /// Bytes per pixel of the harness's own targets: the frame targets (RGBA8 colour, RGBA16F
    /// visibility, 4 B depth-stencil: gl/FrameTargets.h), a visibility read-back (4 floats), and the
    /// accuracy G-buffer (RGBA32F position, R32UI primitive, 4 B depth on the device; 21 B read back).
    static constexpr uint64_t kTargetBytesPerPixel = 16 + 16 + 24 + 21;

    /// The frame targets' bytes at `width` x `height`.
    static uint64_t targetBytes(int width, int height);
    /// What `spec` (a technique of the registry; "auto" and unknown names are skipped: they are resolved
    /// or refused elsewhere) declares it allocates for `in`.
    static ResourceEstimate techniqueBytes(const TechniqueSpec& spec, const ResourceInputs& in);
    /// Throws sb::Error(BadInput) when the scene's `sceneBytes`, the targets at `in`'s frame size and
    /// one of `specs`' estimates together exceed `limitBytes`. `where` begins the line ("" for a run,
    /// "sweep: combination ...: " for a sweep).
    static void check(const std::vector<TechniqueSpec>& specs, const ResourceInputs& in, uint64_t sceneBytes,
                      uint64_t limitBytes, const std::string& where = "");
};

} // namespace sb
