#include "bench/lib/measure/TexelDensity.h"

#include <algorithm>
#include <cmath>

#include "bench/lib/statistics/Statistics.h"
#include "scenes/Math.h"

namespace sb {

namespace {
/// Quarter of a pixel's footprint: small enough that a perspective or paraboloid mapping is linear across
/// it to many digits, large enough that the differences keep most of a double's digits.
constexpr double kStepPixels = 0.25;
} // namespace

glm::dmat2 TexelDensity::screenJacobian(const glm::mat4& cameraViewProj, glm::ivec2 size, const glm::dvec3& p,
                                        const glm::dvec3& u, const glm::dvec3& v) {
    const glm::dmat4 m(cameraViewProj);
    const glm::dvec4 c = m * glm::dvec4(p, 1.0);
    const glm::dvec2 half = 0.5 * glm::dvec2(size);
    // d(c.xy / c.w) / d(direction) = (M_xy dir c.w - c.xy M_w dir) / c.w^2; M times a direction (w = 0).
    auto along = [&](const glm::dvec3& d) {
        const glm::dvec4 dc = m * glm::dvec4(d, 0.0);
        return half * (glm::dvec2(dc) * c.w - glm::dvec2(c) * dc.w) / (c.w * c.w);
    };
    return glm::dmat2(along(u), along(v));
}

std::optional<double> TexelDensity::texelsPerPixel(const MapTexels& maps, size_t light, const ShadedPoint& at,
                                                   const glm::dvec3& normal, const glm::mat4& cameraViewProj,
                                                   glm::ivec2 size) {
    const std::optional<MapPoint> here = maps.texel(light, at, at.position);
    if (!here) return std::nullopt;
    const glm::dvec3 n = glm::normalize(normal);
    const glm::dvec3 u = glm::normalize(glm::cross(n, glm::dvec3(anyPerpendicularUp(glm::vec3(n)))));
    const glm::dvec3 v = glm::cross(n, u);
    const double screenArea =
        std::abs(glm::determinant(screenJacobian(cameraViewProj, size, at.position, u, v)));
    if (!(screenArea > 0.0) || !std::isfinite(screenArea)) return std::nullopt; // seen edge-on
    const double h = kStepPixels / std::sqrt(screenArea);
    auto texelAt = [&](const glm::dvec3& q) { return maps.texel(light, at, q)->texel; };
    const glm::dvec2 du = (texelAt(at.position + h * u) - texelAt(at.position - h * u)) / (2.0 * h);
    const glm::dvec2 dv = (texelAt(at.position + h * v) - texelAt(at.position - h * v)) / (2.0 * h);
    const double texelArea = std::abs(glm::determinant(glm::dmat2(du, dv)));
    const double t = std::sqrt(texelArea / screenArea);
    if (!std::isfinite(t)) return std::nullopt;
    return t;
}

TexelDensity::Summary TexelDensity::summarize(std::vector<double> values) {
    Summary s;
    if (values.empty()) return s;
    std::sort(values.begin(), values.end());
    s.samples = values.size();
    s.min = values.front();
    s.p5 = Statistics::percentileSorted(values, 0.05);
    s.p50 = Statistics::percentileSorted(values, 0.5);
    return s;
}

} // namespace sb
