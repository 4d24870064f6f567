#include "scenes/ShadowPlane.h"

#include <cmath>

#include "core/Error.h"

namespace sb {

ShadowCoord ShadowPlane::project(const glm::vec3& p0, const glm::vec3& towardLight) const {
    float cosine = glm::dot(normal, towardLight);
    // Equation 6's denominator, kept away from 0 with its sign (0 itself counts as positive).
    if (std::abs(cosine) < kMinCosine) cosine = std::signbit(cosine) ? -kMinCosine : kMinCosine;
    ShadowCoord c;
    c.s = glm::dot(normal, origin - p0) / cosine;
    const glm::vec3 d = p0 + c.s * towardLight - origin; // p(s_I) - o
    c.uv = glm::vec2(glm::dot(right, d) / width, glm::dot(up, d) / height);
    return c;
}

std::array<glm::vec4, 3> ShadowPlane::textureMatrix(const glm::vec3& towardLight) const {
    float cosine = glm::dot(normal, towardLight);
    if (std::abs(cosine) < kMinCosine) cosine = std::signbit(cosine) ? -kMinCosine : kMinCosine;
    // s(p) = (n.o - n.p) / (n.L); d = p + s(p) L - o; u = (right / width).d, v = (up / height).d.
    const glm::vec4 s(-normal / cosine, glm::dot(normal, origin) / cosine);
    auto row = [&](const glm::vec3& axis) {
        const float along = glm::dot(axis, towardLight);
        return glm::vec4(axis + along * glm::vec3(s), along * s.w - glm::dot(axis, origin));
    };
    return {row(right / width), row(up / height), s};
}

bool ShadowPlane::solidShadows(const glm::vec3& p0, const glm::vec3& towardLight) const {
    const ShadowCoord c = project(p0, towardLight);
    return c.s > 0.0f && c.uv.x >= 0.0f && c.uv.x <= 1.0f && c.uv.y >= 0.0f && c.uv.y <= 1.0f;
}

void ShadowPlane::validate(const std::string& where) const {
    auto fail = [&](const std::string& what) {
        throw Error(where + ": shadow plane '" + name + "': " + what);
    };
    for (const glm::vec3* v : {&origin, &normal, &right, &up})
        if (!std::isfinite(v->x) || !std::isfinite(v->y) || !std::isfinite(v->z)) fail("non-finite vector");
    if (!(std::isfinite(width) && width > 0.0f && std::isfinite(height) && height > 0.0f))
        fail("width and height must be positive (got " + std::to_string(width) + " x " +
             std::to_string(height) + ")");
    constexpr float kTol = 1e-3f;
    if (std::abs(glm::length(normal) - 1.0f) > kTol || std::abs(glm::length(right) - 1.0f) > kTol ||
        std::abs(glm::length(up) - 1.0f) > kTol)
        fail("normal, right and up must be unit vectors");
    if (std::abs(glm::dot(normal, right)) > kTol || std::abs(glm::dot(normal, up)) > kTol ||
        std::abs(glm::dot(right, up)) > kTol)
        fail("normal, right and up must be perpendicular to each other");
}

} // namespace sb
