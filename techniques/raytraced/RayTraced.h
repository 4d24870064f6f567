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
//   soft  area lights (a rect, disk or sphere emitter, the sun's angular disk): `rays` rays per fragment
//         and light towards stratified points of the emitter (rounded up to a square, side x side
//         strata: scenes/EmitterGrid.h), visibility the fraction unoccluded, each emitter mapped as the
//         reference's reference/LightSampler maps it (shaders/raytraced/emitter.glsl): an unbiased
//         estimate of the quantity the reference computes. A delta light (no extent) gets one ray, as in
//         `hard`.
//   guided  hard's rays only where a depth map of the light cannot decide (techniques/raytraced/
//         GuidedRays.h: the rule and why it is conservative); a pass "depth" renders the maps.
// An area light is traced at its centre in `hard` mode.
//
// `temporal=true` (soft only): each frame draws a fresh jitter of the strata (the frame index enters the
// sequence's seed) and the visibility shown is an exponential moving average over frames, kept in a
// history image: a running mean over the first 1/kHistoryWeight frames, then a weight of kHistoryWeight
// for the new frame. The history restarts whenever the camera or the scene moves (no reprojection: it
// is an accumulation for still frames).
#include <cstdint>
#include <string>
#include <vector>

#include "core/NameTable.h"
#include "scenes/Scene.h"
#include "shading/Defines.h"
#include "techniques/PropertySet.h"
#include "techniques/TechniqueInfo.h"

namespace sb {

struct RayTraced {
    static constexpr const char* kName = "raytraced";
    static constexpr const char* kMode = "mode";
    static constexpr const char* kRays = "rays";
    static constexpr const char* kTemporal = "temporal";
    /// temporal: the new frame's weight in the moving average once the running mean has reached it
    /// (shaders/raytraced/lighting.frag, RT_HISTORY_WEIGHT): the average then spans ~1/0.1 = 10 frames.
    static constexpr float kHistoryWeight = 0.1f;
    /// temporal: the history's texel (RGBA32F, a channel per light) and its two layers (read the last
    /// frame's, write this one's).
    static constexpr uint64_t kHistoryTexelBytes = 16;
    static constexpr uint64_t kHistoryLayers = 2;
    /// `rays`' range: 256 is a 16 x 16 grid.
    static constexpr int kMaxRays = 256;
    /// Why there is no GL form: the registry's one-line refusal of `-t raytraced` on GL.
    static constexpr const char* kGlRefusal =
        "GL has no ray queries: ray-traced shadows need VK_KHR_ray_query (use --api vulkan --driver "
        "mesa-25.0.7)";
    /// Where the Vulkan extensions are found when the device lacks them (the capabilities' hint).
    static constexpr const char* kDriverHint = "the driver entry mesa-25.0.7 has them: --driver mesa-25.0.7";

    enum class Mode { Hard, Soft, Guided };
    struct ModeEntry {
        Mode value;
        const char* name;   ///< the value of `mode`
        const char* define; ///< the define shaders/raytraced/lighting.frag selects it by
    };
    static const NameTable<ModeEntry>& modes();
    /// The mode `properties` select.
    static Mode mode(const PropertySet& properties);
    /// Whether `properties` accumulate over frames: temporal=true in soft mode (hard is exact already).
    static bool temporal(const PropertySet& properties);

    /// The side of the stratified grid `properties` ask for: `rays` rounded up to a square (16 -> 4,
    /// 10 -> 4), as the reference rounds its samples (scenes/EmitterGrid.h).
    static int raySide(const PropertySet& properties);

    /// The declaration at the default mode (hard).
    static TechniqueInfo declaration();
    /// The passes of `mode`: structures and lighting; guided's depth maps between them.
    static std::vector<std::string> passes(Mode mode);
    /// What `mode` delivers: soft_shadows too in `soft`.
    static EffectMask effects(Mode mode);
    /// The defines of the mode `properties` select, for `scene`: RT_MODE_HARD=1, RT_MODE_GUIDED=1, or
    /// RT_MODE_SOFT=1 with RT_SIDE=<raySide> and the scene's emitters (SB_EMITTERS,
    /// techniques/raytraced/LightEmitter.h), and under temporal() RT_TEMPORAL=1 with RT_HISTORY_WEIGHT.
    static void addModeDefines(const PropertySet& properties, const Scene& scene, Defines& defines);

    /// The counters of one frame, in this order:
    ///   structures_built  acceleration structures built or rebuilt inside the frame (the top level of a
    ///                     scene whose casters move; 0 for a static scene, whose structures are built once
    ///                     before the first frame)
    ///   structure_bytes   the storage of every structure, bottom levels and top level
    ///   rays_traced       shadow rays the lighting pass traced: per shaded fragment, one per light that
    ///                     reaches it and whose shadow applies (soft: per area light, one per stratum whose
    ///                     emitter point is valid and above the surface's horizon); counted on the device,
    ///                     exact
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
