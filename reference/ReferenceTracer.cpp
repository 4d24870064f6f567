#include "reference/ReferenceTracer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <thread>

#include "core/CpuAllocation.h"
#include "core/Error.h"
#include "reference/LightSampler.h"

namespace sb {

namespace {

constexpr int kPacket = 16; ///< rtcOccluded16
constexpr int kTile = 4;    ///< hard shadows: 4x4 pixel tiles fill one packet
constexpr float kInfinity = std::numeric_limits<float>::infinity();
/// Rays towards a point stop this relative distance short of it, so geometry at (or rounding onto)
/// the light itself, e.g. a lantern's bulb, does not occlude. 2^-12 is 2^11 float ulps: well above
/// the rounding of the distance, well below any caster gap that matters.
constexpr float kShortenTfar = 1.0f - 0x1.0p-12f;

/// Per-trace constants of the light, so the per-pixel path normalises nothing.
struct LightFrame {
    explicit LightFrame(const Light& light)
        : type(light.type), position(light.position), towardsDirectional(-glm::normalize(light.direction)),
          cosOuter(std::cos(glm::radians(light.spotOuterDeg))) {}
    LightType type;
    glm::vec3 position;
    glm::vec3 towardsDirectional; ///< -direction, unit (also the spot's axis, negated)
    float cosOuter;
};

/// Direction and distance from a receiver towards the light's centre (hard shadows, facing test).
struct CentreRay {
    glm::vec3 towards{0.0f}; ///< unit
    float distance = kInfinity;
    bool arrives = false; ///< false: outside a spot's cone, or at the light itself
};

CentreRay centreRay(const LightFrame& light, const glm::vec3& p) {
    CentreRay r;
    if (light.type == LightType::Directional) {
        r.towards = light.towardsDirectional;
        r.arrives = true;
        return r;
    }
    const glm::vec3 d = light.position - p;
    r.distance = glm::length(d);
    if (!(r.distance > 0.0f)) return r;
    r.towards = d / r.distance;
    r.arrives = true;
    if (light.type == LightType::Spot) {
        // Outside the outer cone no light arrives at all, so nothing can be lit there: 0 (the same
        // value a shadowed sample gets; the accuracy mask uses n.L, so such samples still count as
        // "no light" on both sides).
        r.arrives = glm::dot(r.towards, light.towardsDirectional) >= light.cosOuter;
    }
    return r;
}

/// A packet whose every lane holds a valid empty ray (origin, direction and [tnear, tfar] all 0).
/// Observed with Debian's Embree (assertions on) on an AVX2 machine, where rtcOccluded16 runs 8-wide:
/// its coherent path asserted `ray.valid()` on the lanes outside the valid mask too, and aborted when the
/// uninitialised stack there held a NaN. Zeroing costs one memset per packet of 16 rays.
RTCRay16 emptyPacket() {
    return RTCRay16{};
}

void setRay(RTCRay16& rays, int lane, const glm::vec3& o, const glm::vec3& d, float tfar) {
    rays.org_x[lane] = o.x;
    rays.org_y[lane] = o.y;
    rays.org_z[lane] = o.z;
    rays.dir_x[lane] = d.x;
    rays.dir_y[lane] = d.y;
    rays.dir_z[lane] = d.z;
    rays.tnear[lane] = 0.0f;
    rays.tfar[lane] = tfar;
    rays.time[lane] = 0.0f;
    rays.mask[lane] = 0xFFFFFFFFu;
    rays.id[lane] = unsigned(lane);
    rays.flags[lane] = 0;
}

/// One trace() call's shared state; workers pull bands of work from `next`.
struct TraceJob {
    const Scene& scene;
    const EmbreeScene& embree;
    const GBuffer& gbuffer;
    const LightFrame light;
    LightSampler sampler;
    bool hard = true;
    int side = 1; ///< soft: strata per axis
    uint32_t seed = 1;
    bool castsShadows = true; ///< the light's "casts_shadows"
    VisibilityImage* out = nullptr;
    std::atomic<int> next{0};
    std::atomic<uint64_t> rayCount{0};

    /// The seen side's normal (ReferenceTracer::seenNormalAt).
    glm::vec3 normal(size_t pixel) const {
        return gbuffer.seenNormal(pixel,
                                  embree.geometricNormal(gbuffer.instance(pixel), gbuffer.primitive[pixel]));
    }
    /// False for a light that casts no shadow and on an instance that receives none: nothing
    /// occludes the light there (the techniques' common/lighting.glsl, shadowApplies).
    bool occludable(size_t pixel) const {
        return castsShadows && scene.instances[gbuffer.instance(pixel)].receivesShadow;
    }
    uint64_t hardTile(int tx, int ty) const;
    uint64_t softPixel(size_t pixel) const;
    void work();
};

/// Hard shadows of one 4x4 tile in one packet: neighbouring pixels see nearly the same BVH nodes,
/// which is what the coherent flag tells Embree to exploit.
uint64_t TraceJob::hardTile(int tx, int ty) const {
    RTCRay16 rays = emptyPacket();
    alignas(64) int valid[kPacket];
    size_t pixelOf[kPacket];
    int active = 0;
    for (int lane = 0; lane < kPacket; ++lane) {
        valid[lane] = 0;
        const int x = tx * kTile + lane % kTile, y = ty * kTile + lane / kTile;
        if (x >= gbuffer.width || y >= gbuffer.height) continue;
        const size_t pixel = size_t(y) * size_t(gbuffer.width) + size_t(x);
        pixelOf[lane] = pixel;
        if (!gbuffer.covered(pixel)) continue;
        const glm::vec3 p(gbuffer.position[pixel]);
        const glm::vec3 n = normal(pixel);
        const CentreRay c = centreRay(light, p);
        if (!c.arrives || !(glm::dot(n, c.towards) > 0.0f)) continue; // stays 0: no direct light
        if (!occludable(pixel)) {
            out->value[pixel] = 1.0f;
            continue;
        }
        const glm::vec3 o = p + n * ReferenceTracer::originEpsilon(p);
        if (c.distance == kInfinity)
            setRay(rays, lane, o, c.towards, kInfinity);
        else
            setRay(rays, lane, o, light.position - o, kShortenTfar); // tfar 1 = at the light
        valid[lane] = -1;
        ++active;
    }
    if (active == 0) return 0;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    rtcOccluded16(valid, embree.handle(), &context, &rays);
    for (int lane = 0; lane < kPacket; ++lane)
        if (valid[lane]) out->value[pixelOf[lane]] = rays.tfar[lane] >= 0.0f ? 1.0f : 0.0f; // -inf: hit
    return uint64_t(active);
}

/// Soft shadow of one pixel: side^2 stratified emitter samples, 16 per packet (one origin, one
/// emitter: coherent too).
uint64_t TraceJob::softPixel(size_t pixel) const {
    const glm::vec3 p(gbuffer.position[pixel]);
    const glm::vec3 n = normal(pixel);
    const CentreRay c = centreRay(light, p);
    if (!c.arrives || !(glm::dot(n, c.towards) > 0.0f)) return 0; // stays 0: no direct light
    const glm::vec3 o = p + n * ReferenceTracer::originEpsilon(p);
    uint64_t rng = LightSampler::pixelSeed(seed, pixel);
    const int total = side * side;
    int lit = 0;
    uint64_t cast = 0;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    for (int first = 0; first < total; first += kPacket) {
        RTCRay16 rays = emptyPacket();
        alignas(64) int valid[kPacket];
        int active = 0;
        for (int lane = 0; lane < kPacket; ++lane) {
            valid[lane] = 0;
            const int k = first + lane;
            if (k >= total) continue;
            const glm::vec2 u = LightSampler::stratumPoint(k % side, k / side, side, rng);
            const LightSampler::Sample s = sampler.sample(o, u);
            // A sample under the receiver's horizon or on the emitter's dark side sends no light: it
            // counts as not seen (stays out of `lit`) without a ray.
            if (!s.valid || !(glm::dot(n, s.direction) > 0.0f)) continue;
            if (!occludable(pixel)) { // seen unless occluded, and nothing occludes it here
                ++lit;
                continue;
            }
            const float tfar = s.distance == kInfinity ? kInfinity : s.distance * kShortenTfar;
            setRay(rays, lane, o, s.direction, tfar);
            valid[lane] = -1;
            ++active;
        }
        if (active == 0) continue;
        rtcOccluded16(valid, embree.handle(), &context, &rays);
        for (int lane = 0; lane < kPacket; ++lane)
            if (valid[lane] && rays.tfar[lane] >= 0.0f) ++lit;
        cast += uint64_t(active);
    }
    out->value[pixel] = float(lit) / float(total);
    return cast;
}

void TraceJob::work() {
    const int tileRows = (gbuffer.height + kTile - 1) / kTile;
    const int tileCols = (gbuffer.width + kTile - 1) / kTile;
    const int items = hard ? tileRows : gbuffer.height;
    uint64_t cast = 0;
    // Work items are one row of tiles (hard) or one pixel row (soft): small enough to balance the
    // uneven cost of shadowed and open regions, large enough that the counter is not contended.
    for (int item = next.fetch_add(1); item < items; item = next.fetch_add(1)) {
        if (hard) {
            for (int tx = 0; tx < tileCols; ++tx) cast += hardTile(tx, item);
        } else {
            for (int x = 0; x < gbuffer.width; ++x) {
                const size_t pixel = size_t(item) * size_t(gbuffer.width) + size_t(x);
                if (gbuffer.covered(pixel)) cast += softPixel(pixel);
            }
        }
    }
    rayCount.fetch_add(cast);
}

/// Rejects a G-buffer the tracer cannot index safely (before the timed part).
void validate(const Scene& scene, const GBuffer& g) {
    if (g.width <= 0 || g.height <= 0)
        throw Error("reference: empty G-buffer (" + std::to_string(g.width) + "x" + std::to_string(g.height) +
                    ")");
    if (g.position.size() != g.size() || g.primitive.size() != g.size())
        throw Error("reference: G-buffer " + std::to_string(g.width) + "x" + std::to_string(g.height) +
                    " has " + std::to_string(g.position.size()) + " positions and " +
                    std::to_string(g.primitive.size()) + " primitive ids, expected " +
                    std::to_string(g.size()) + " of each");
    if (!g.backFacing.empty() && g.backFacing.size() != g.size())
        throw Error("reference: G-buffer has " + std::to_string(g.backFacing.size()) +
                    " back-face flags, expected none or " + std::to_string(g.size()));
    for (size_t i = 0; i < g.size(); ++i) {
        if (!g.covered(i)) continue;
        const uint32_t inst = g.instance(i);
        if (inst >= scene.instances.size())
            throw Error("reference: G-buffer sample " + std::to_string(i) + " names object id " +
                        std::to_string(inst + 1) + ", the scene has " +
                        std::to_string(scene.instances.size()) + " instances");
        if (g.primitive[i] >= scene.meshes[scene.instances[inst].mesh].triangleCount())
            throw Error("reference: G-buffer sample " + std::to_string(i) + " names triangle " +
                        std::to_string(g.primitive[i]) + " of instance " + std::to_string(inst) +
                        ", which has fewer");
    }
}

} // namespace

ReferenceTracer::ReferenceTracer(const Scene& scene, const EmbreeScene& embree)
    : mScene(scene), mEmbree(embree) {}

float ReferenceTracer::originEpsilon(const glm::vec3& p) {
    // Float spacing (ulp) at magnitude m is between 2^-24 m and 2^-23 m. A G-buffer position is off
    // its triangle's plane by a few ulps of its largest coordinate: the model transform's float sums,
    // the rasteriser's interpolation (llvmpipe and GPUs compute in IEEE binary32) and Embree's own
    // watertight test, all relative to that coordinate. 2^-18 is 32 ulps (2^-23 m each): a wide margin
    // over those few ulps, yet small against the scene: 3.8e-4 at |p| = 100, 0.38 at |p| = 1e5 (where
    // one ulp is already 0.008). A fixed 1e-3 is below one ulp at 1e5 and is lost in the rounding of
    // p + n*eps, so about a third of lit samples on sloped surfaces self-occlude (ReferenceTest
    // shows it). The brief's 2^-14 (512 ulps) was rejected: at 1e5 it lifts ground rays by 6 units,
    // above a 3-unit-high caster, turning real shadows into light.
    constexpr float kRelative = 0x1.0p-18f;
    // Near the origin the relative term vanishes while absolute errors (GL interpolation of a
    // position attribute, unprojection) do not: 1e-4 scene units (0.1 mm for metres) floor.
    constexpr float kAbsolute = 1e-4f;
    const float m = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    return std::max(kAbsolute, kRelative * m);
}

int ReferenceTracer::threadCount(int requested) {
    return requested > 0 ? requested : allocatedCpuCount();
}

glm::vec3 ReferenceTracer::seenNormalAt(const GBuffer& gbuffer, size_t pixel) const {
    return gbuffer.seenNormal(pixel,
                              mEmbree.geometricNormal(gbuffer.instance(pixel), gbuffer.primitive[pixel]));
}

VisibilityImage ReferenceTracer::trace(const GBuffer& gbuffer, int light, const Options& options,
                                       TraceStats* stats) const {
    if (light < 0 || size_t(light) >= mScene.lights.size())
        throw Error("reference: light " + std::to_string(light) + " out of range (scene '" + mScene.name +
                    "' has " + std::to_string(mScene.lights.size()) + " lights)");
    validate(mScene, gbuffer);
    VisibilityImage image;
    image.width = gbuffer.width;
    image.height = gbuffer.height;
    image.value.resize(gbuffer.size());
    for (size_t i = 0; i < gbuffer.size(); ++i) image.value[i] = gbuffer.covered(i) ? 0.0f : -1.0f;

    TraceJob job{mScene, mEmbree, gbuffer, LightFrame(mScene.lights[size_t(light)]),
                 LightSampler(mScene.lights[size_t(light)])};
    job.hard = options.forceHard || job.sampler.isDelta();
    job.side = job.hard ? 1 : LightSampler::gridSide(std::max(1, options.softSamples));
    job.seed = options.seed;
    job.castsShadows = mScene.lights[size_t(light)].castsShadows;
    job.out = &image;

    const int threads = threadCount(options.threads);
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::thread> workers;
    for (int t = 1; t < threads; ++t) workers.emplace_back([&job] { job.work(); });
    job.work(); // the calling thread is worker 0
    for (auto& w : workers) w.join();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    if (stats) {
        stats->rays = job.rayCount.load();
        stats->seconds = seconds;
        stats->threads = threads;
        stats->raysPerSecondPerThread = seconds > 0.0 ? double(stats->rays) / seconds / threads : 0.0;
        stats->samplesPerPixel = job.side * job.side;
        stats->noiseBound = job.hard ? 0.0 : 1.96 * std::sqrt(0.25 / double(stats->samplesPerPixel));
    }
    return image;
}

} // namespace sb
