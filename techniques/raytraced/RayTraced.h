#pragma once
// `raytraced`: shadows by tracing rays from the visible surface towards each light, after Boksansky,
// Wimmer and Bittner, "Ray Traced Shadows: Maintaining Real-Time Frame Rates" (Ray Tracing Gems, ch. 13),
// with the rays traced from the lighting pass's fragment shader through the Vulkan ray query extension
// (VK_KHR_ray_query, GLSL GL_EXT_ray_query) against acceleration structures
// (VK_KHR_acceleration_structure; techniques/raytraced/AccelerationStructures.h).
//
// The declaration both its forms would take (techniques/TechniqueInfo.h) and what they would share: the
// property names, the modes and their shader defines, the counters. It has a Vulkan form only
// (RayTracedVulkan): GL has no ray queries, which the registry says when it is asked for on GL (kGlRefusal).
//
// Modes (property `mode`, one shader define each, all in shaders/raytraced/lighting.frag):
//   hard  one ray per fragment and light towards the light's centre (its position, or against its
//         direction), 1 lit, 0 shadowed: the exact hard shadow the Embree reference computes.
// An area light is traced at its centre in `hard` mode.
#include <cstdint>
#include <string>

#include "core/NameTable.h"
#include "shading/Defines.h"
#include "techniques/PropertySet.h"
#include "techniques/TechniqueInfo.h"

namespace sb {

struct RayTraced {
    static constexpr const char* kName = "raytraced";
    static constexpr const char* kMode = "mode";
    /// Why there is no GL form: the registry's one-line refusal of `-t raytraced` on GL.
    static constexpr const char* kGlRefusal =
        "GL has no ray queries: ray-traced shadows need VK_KHR_ray_query (use --api vulkan --driver "
        "mesa-25.0.7)";
    /// Where the Vulkan extensions are found when the device lacks them (the capabilities' hint).
    static constexpr const char* kDriverHint = "the driver entry mesa-25.0.7 has them: --driver mesa-25.0.7";

    enum class Mode { Hard };
    struct ModeEntry {
        Mode value;
        const char* name;   ///< the value of `mode`
        const char* define; ///< the define shaders/raytraced/lighting.frag selects it by
    };
    static const NameTable<ModeEntry>& modes();
    /// The mode `properties` select.
    static Mode mode(const PropertySet& properties);

    static TechniqueInfo declaration();
    /// The mode's define (RT_MODE_HARD=1) added to `defines`.
    static void addModeDefines(Mode mode, Defines& defines);

    /// The counters of one frame, in this order:
    ///   structures_built  acceleration structures built or rebuilt inside the frame (the top level of a
    ///                     scene whose casters move; 0 for a static scene, whose structures are built once
    ///                     before the first frame)
    ///   structure_bytes   the storage of every structure, bottom levels and top level
    ///   rays_traced       shadow rays the lighting pass traced: per shaded fragment, one per light that
    ///                     reaches it and whose shadow applies; counted on the device, exact
    static Counters counters(uint32_t structuresBuilt, uint64_t structureBytes, uint64_t raysTraced);
    /// The structures' build times, measured once before the first frame (AccelerationStructures), in ms;
    /// times, not work (their names end in _ms: the perf gate's exact-work layer leaves them out,
    /// bench/lib/gate/WorkColumns.h):
    ///   bottom_levels_build_ms  the one submission that builds every mesh's bottom level
    ///   top_level_build_ms      the top level's build over the casters, which a frame whose casters
    ///                           moved repeats inside its command buffer (the `structures` pass)
    static Counters buildTimes(double bottomLevelsMs, double topLevelMs);
};

} // namespace sb
