#include "reference/LightSampler.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/constants.hpp>

#include "scenes/EmitterGrid.h"
#include "scenes/Math.h"

namespace sb {

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

/// Unit vector at polar angle acos(cosTheta) and azimuth phi around the orthonormal frame (t, b, axis).
glm::vec3 coneDirection(float cosTheta, float phi, const glm::vec3& t, const glm::vec3& b,
                        const glm::vec3& axis) {
    const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    return sinTheta * std::cos(phi) * t + sinTheta * std::sin(phi) * b + cosTheta * axis;
}

/// Orthonormal tangents of a unit axis.
void tangentFrame(const glm::vec3& axis, glm::vec3& t, glm::vec3& b) {
    t = glm::normalize(glm::cross(anyPerpendicularUp(axis), axis));
    b = glm::cross(axis, t);
}

/// Shirley-Chiu concentric map of the unit square onto the unit disk: area-preserving and keeps
/// strata compact (a polar map would turn square strata into thin wedges near the centre).
glm::vec2 concentricDisk(const glm::vec2& u) {
    const glm::vec2 s = 2.0f * u - 1.0f;
    if (s.x == 0.0f && s.y == 0.0f) return glm::vec2(0.0f);
    const float quarter = 0.25f * glm::pi<float>();
    if (std::abs(s.x) > std::abs(s.y)) {
        const float phi = quarter * (s.y / s.x);
        return s.x * glm::vec2(std::cos(phi), std::sin(phi));
    }
    const float phi = 2.0f * quarter - quarter * (s.x / s.y);
    return s.y * glm::vec2(std::cos(phi), std::sin(phi));
}

} // namespace

LightSampler::LightSampler(const Light& light) : mLight(light) {
    mW = glm::normalize(light.direction);
    tangentFrame(mW, mU, mV);
    if (light.type == LightType::Directional) {
        const float a = glm::radians(light.angularRadiusDeg);
        mDelta = light.shape == LightShape::Point || !(a > 0.0f);
        mCosConeMax = std::cos(a);
        return;
    }
    switch (light.shape) {
    case LightShape::Point:
        mDelta = true;
        break;
    case LightShape::Rect:
        mDelta = !(light.size.x > 0.0f && light.size.y > 0.0f);
        break;
    case LightShape::Disk:
    case LightShape::Sphere:
        mDelta = !(light.size.x > 0.0f);
        break;
    }
}

LightSampler::Sample LightSampler::sample(const glm::vec3& origin, const glm::vec2& u) const {
    if (mLight.type == LightType::Directional) return sampleCone(u);
    switch (mLight.shape) {
    case LightShape::Rect:
        return sampleRect(origin, u);
    case LightShape::Disk:
        return sampleDisk(origin, u);
    case LightShape::Sphere:
        return sampleSphere(origin, u);
    case LightShape::Point:
        break;
    }
    return towardsPlanarPoint(origin, mLight.position);
}

LightSampler::Sample LightSampler::sampleRect(const glm::vec3& origin, const glm::vec2& u) const {
    const glm::vec3 point =
        mLight.position + (u.x - 0.5f) * mLight.size.x * mU + (u.y - 0.5f) * mLight.size.y * mV;
    return towardsPlanarPoint(origin, point);
}

LightSampler::Sample LightSampler::sampleDisk(const glm::vec3& origin, const glm::vec2& u) const {
    const glm::vec2 d = mLight.size.x * concentricDisk(u);
    return towardsPlanarPoint(origin, mLight.position + d.x * mU + d.y * mV);
}

LightSampler::Sample LightSampler::towardsPlanarPoint(const glm::vec3& origin, const glm::vec3& point) const {
    Sample s;
    const glm::vec3 d = point - origin;
    s.distance = glm::length(d);
    if (!(s.distance > 0.0f)) return s;
    s.direction = d / s.distance;
    // One-sided emitter: light leaves along +w only, so a receiver behind the emitter's plane (or on
    // it) gets nothing from it. Point-shaped lights emit everywhere.
    s.valid = mLight.shape == LightShape::Point || glm::dot(s.direction, mW) < 0.0f;
    return s;
}

LightSampler::Sample LightSampler::sampleSphere(const glm::vec3& origin, const glm::vec2& u) const {
    // Uniform in solid angle over the cone that the sphere subtends (its visible cap): cos(theta)
    // uniform in [cos(alpha), 1]. Each direction hits the sphere; the ray ends at the near hit.
    Sample s;
    const float r = mLight.size.x;
    const glm::vec3 toCentre = mLight.position - origin;
    const float d = glm::length(toCentre);
    const float phi = 2.0f * glm::pi<float>() * u.y;
    if (!(d > r)) {
        // Inside the emitter: every direction sees it; the ray ends where it leaves the sphere.
        const glm::vec3 dir =
            coneDirection(1.0f - 2.0f * u.x, phi, glm::vec3(1, 0, 0), glm::vec3(0, 0, 1), glm::vec3(0, 1, 0));
        const float b = glm::dot(dir, toCentre), c = d * d - r * r;
        s.direction = dir;
        s.distance = b + std::sqrt(std::max(0.0f, b * b - c));
        s.valid = true;
        return s;
    }
    const glm::vec3 axis = toCentre / d;
    glm::vec3 t, bt;
    tangentFrame(axis, t, bt);
    const float sinAlpha = r / d;
    const float cosAlpha = std::sqrt(std::max(0.0f, 1.0f - sinAlpha * sinAlpha));
    const float cosTheta = 1.0f - u.x * (1.0f - cosAlpha);
    s.direction = coneDirection(cosTheta, phi, t, bt, axis);
    // Near intersection with the sphere: t = d cos(theta) - sqrt(r^2 - d^2 sin^2(theta)).
    const float sin2 = std::max(0.0f, 1.0f - cosTheta * cosTheta);
    s.distance = d * cosTheta - std::sqrt(std::max(0.0f, r * r - d * d * sin2));
    s.valid = s.distance > 0.0f;
    return s;
}

LightSampler::Sample LightSampler::sampleCone(const glm::vec2& u) const {
    // Directional sun: uniform in solid angle within the angular disk around -direction.
    Sample s;
    const float cosTheta = 1.0f - u.x * (1.0f - mCosConeMax);
    s.direction = coneDirection(cosTheta, 2.0f * glm::pi<float>() * u.y, mU, mV, -mW);
    s.distance = kInfinity;
    s.valid = true;
    return s;
}

int LightSampler::gridSide(int samples) {
    return emitterGridSide(samples);
}

glm::vec2 LightSampler::stratumPoint(int i, int j, int side, uint64_t& rng) {
    const float inv = 1.0f / float(side);
    const float jx = nextUniform(rng), jy = nextUniform(rng);
    // min() keeps the point inside [0,1) when rounding would push (side-1 + ~1)/side to 1.
    return glm::vec2(std::min((float(i) + jx) * inv, 0x1.fffffep-1f),
                     std::min((float(j) + jy) * inv, 0x1.fffffep-1f));
}

uint64_t LightSampler::pixelSeed(uint32_t seed, uint64_t pixel) {
    uint64_t z = (uint64_t(seed) << 40) ^ pixel ^ 0x5DEECE66Dull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

float LightSampler::nextUniform(uint64_t& rng) {
    uint64_t z = (rng += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return float(z >> 40) * 0x1.0p-24f;
}

} // namespace sb
