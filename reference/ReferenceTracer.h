#pragma once
// Exact visibility by ray casting: for every covered G-buffer sample and one light, the
// fraction of the light that the sample sees.
//   hard (Light::shape == Point, or forced): one occlusion ray per sample towards the light: 1 lit,
//       0 shadowed;
//   soft (area lights: rect, disk, sphere; directional disk = angular sun): N stratified samples over
//       the emitter, visibility = unoccluded fraction, with its noise bound.
// n is the normal of the side the camera sees: the geometric normal, negated on a back face
// (GBuffer::seenNormal, the rasteriser's gl_FrontFacing), as every technique turns its shading normal. A back
// face, e.g. the inside of a closed caster seen from a camera within it, is judged from the inside: a
// ray from its outer side would call lit what no light reaches. Samples whose n faces away from the
// light (n.L <= 0, L towards the light's centre) are 0 (no direct light), and so are spot-light samples
// outside the outer cone (no light arrives there; Light::range, an attenuation, is not applied). Soft:
// emitter samples below the receiver's horizon count as not seen (see reference/LightSampler.h for what
// "fraction of the light" means). Rays start at p + n * originEpsilon(p, n) on the seen side, where the
// epsilon follows the float spacing of each of p's coordinates (a fixed one fails at |p| ~ 1e5; one from
// the largest coordinate alone lifts a ground at y = 0 far off its plane there). Rays go out in packets of 16
// (rtcOccluded16) over image tiles, on a thread pool.
#include <cstdint>
#include <vector>

#include "reference/EmbreeScene.h"
#include "reference/GBuffer.h"
#include "scenes/Scene.h"

namespace sb {

/// Per-sample visibility of one light; -1 where the G-buffer has no geometry.
struct VisibilityImage {
    int width = 0, height = 0;
    std::vector<float> value;
};

struct TraceStats {
    uint64_t rays = 0;
    double seconds = 0.0; ///< wall time of the tracing
    int threads = 1;
    double raysPerSecondPerThread = 0.0;
    /// Soft: the largest 95% half-width of a per-pixel estimate, 1.96 * sqrt(v(1-v)/N) at its worst
    /// (v = 0.5) for plain Monte Carlo; stratification only lowers it. Hard: 0.
    double noiseBound = 0.0;
    int samplesPerPixel = 1;
};

class ReferenceTracer {
public:
    struct Options {
        int softSamples = 64;   ///< per pixel for area lights; rounded up to a square (stratified grid)
        int threads = 0;        ///< 0 = the CPUs the process was given (threadCount)
        uint32_t seed = 1;      ///< jitter of the strata (same seed, same image)
        bool forceHard = false; ///< treat area lights as their centre point
    };

    ReferenceTracer(const Scene& scene, const EmbreeScene& embree);
    /// Visibility of `scene.lights[light]` at every covered sample. Throws sb::Error when `light` is
    /// out of range or the G-buffer is empty.
    VisibilityImage trace(const GBuffer& gbuffer, int light, const Options& options,
                          TraceStats* stats = nullptr) const;
    /// Normal of the side of a covered sample the camera sees: its geometric normal (from EmbreeScene)
    /// negated where the G-buffer saw a back face (GBuffer::seenNormal). The tracer's rays start on this
    /// side, and the accuracy judge's n.L mask uses it.
    glm::vec3 seenNormalAt(const GBuffer& gbuffer, size_t pixel) const;
    /// Ray-origin offset along the unit normal `n` of a sample at `p`: 32 float spacings of each
    /// coordinate, weighted by how far an error in that coordinate moves p off its plane, with an
    /// absolute floor for points near the origin: max(1e-4, 32 * sum_i |n_i| spacing(p_i)), where
    /// spacing(x) is the gap from |x| to the next float (the why, with measured numbers, in the .cpp).
    /// 1e-4 wherever every coordinate is below 16; independent of how far p lies along a coordinate n
    /// does not point in (a ground at y = 0 gets 1e-4 at x = z = 1e5 too).
    static float originEpsilon(const glm::vec3& p, const glm::vec3& n);
    /// The threads trace() runs for Options::threads = `requested`: `requested` when above 0, else the
    /// CPUs of the process's affinity mask (core/CpuAllocation.h), never the node's: a Slurm task or a
    /// `taskset` pins the process to its share, and more threads than that only take turns on it.
    static int threadCount(int requested);

private:
    const Scene& mScene;
    const EmbreeScene& mEmbree;
};

} // namespace sb
