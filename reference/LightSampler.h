#pragma once
// Points and directions on a light's emitter for the reference's soft shadows, from a
// stratified, jittered sqrt(N) x sqrt(N) grid over [0,1)^2 mapped onto the emitter by an
// area-preserving (rect, disk) or solid-angle-preserving (sphere, directional disk) map, so the
// strata stay equal-measure pieces of the emitter.
//
// What the reference's soft visibility means (a definition, chosen for comparability): the
// UNWEIGHTED fraction of the emitter that a receiver point sees.
//   - rect, disk (one-sided, emitting towards Light::direction): the fraction of the emitter's AREA
//     visible, each area element counting the same; no cosine or 1/r^2 weighting, so the value is a
//     pure visibility, independent of the shading model. Emitter points the receiver is behind
//     (the receiver on the non-emitting side) or below the receiver's horizon count as not seen.
//   - sphere: the fraction of the SOLID ANGLE of the visible spherical cap (the part of the sphere
//     the point can see) that is unoccluded; for a uniform-radiance sphere this is also the exact
//     irradiance ratio up to the cosine. A point inside the sphere light samples all directions.
//   - directional + disk/sphere shape (the sun): directions uniform in solid angle within the cone of
//     half-angle angularRadiusDeg around -direction. A directional Rect has no angular meaning and is
//     treated as that disk too.
// Frame of rect and disk: w = normalize(direction); u = normalize(cross(anyPerpendicularUp(w), w)),
// v = cross(w, u); the rect spans size.x along u and size.y along v, centred on position; the disk
// has radius size.x. A light with a zero extent (size, radius or angle) is a delta light: isDelta().
#include <cstdint>

#include <glm/glm.hpp>

#include "scenes/Scene.h"

namespace sb {

class LightSampler {
public:
    /// One emitter sample seen from a ray origin.
    struct Sample {
        glm::vec3 direction{0.0f}; ///< unit, from the origin towards the emitter point
        float distance = 0.0f;     ///< to the emitter point; +infinity for directional lights
        bool valid = false;        ///< false: the point cannot receive light from this sample
    };

    explicit LightSampler(const Light& light);

    /// True when the light has no extent (Point shape or zero size / angle): one ray, hard shadow.
    bool isDelta() const { return mDelta; }
    /// The emitter sample for `u` in [0,1)^2 seen from `origin`.
    Sample sample(const glm::vec3& origin, const glm::vec2& u) const;

    /// Side of the stratified grid for at least `samples` samples (rounded up to a square, >= 1;
    /// scenes/EmitterGrid.h, which the ray-traced soft shadows round by too).
    static int gridSide(int samples);
    /// Jittered point of stratum (i, j) of a side x side grid; `rng` is the per-pixel state.
    static glm::vec2 stratumPoint(int i, int j, int side, uint64_t& rng);
    /// Seeds a pixel's generator from the user seed and the pixel index (a SplitMix64 finaliser:
    /// neighbouring pixels get unrelated streams, and the image depends on nothing else).
    static uint64_t pixelSeed(uint32_t seed, uint64_t pixel);
    /// Uniform float in [0, 1) from the state (SplitMix64 step; 24 bits so the float is exact).
    static float nextUniform(uint64_t& rng);

private:
    Sample sampleRect(const glm::vec3& origin, const glm::vec2& u) const;
    Sample sampleDisk(const glm::vec3& origin, const glm::vec2& u) const;
    Sample sampleSphere(const glm::vec3& origin, const glm::vec2& u) const;
    Sample sampleCone(const glm::vec2& u) const;
    /// The sample towards a point on the one-sided rect/disk emitter.
    Sample towardsPlanarPoint(const glm::vec3& origin, const glm::vec3& point) const;

    Light mLight;
    bool mDelta = true;
    glm::vec3 mW{0.0f, -1.0f, 0.0f}, mU{1.0f, 0.0f, 0.0f}, mV{0.0f, 0.0f, 1.0f};
    float mCosConeMax = 1.0f; ///< directional: cos(angularRadius)
};

} // namespace sb
