#include "techniques/virtual/VirtualMapTexels.h"

#include <algorithm>
#include <cmath>

#include "scenes/Math.h"
#include "techniques/FlatLightFits.h"

namespace sb {

namespace {

/// d(scale * (m p).xy / (m p).w) / d(direction) at `p` for the directions `u` and `v` (columns).
glm::dmat2 projectedJacobian(const glm::mat4& matrix, glm::dvec2 scale, const glm::dvec3& p,
                             const glm::dvec3& u, const glm::dvec3& v) {
    const glm::dmat4 m(matrix);
    const glm::dvec4 c = m * glm::dvec4(p, 1.0);
    auto along = [&](const glm::dvec3& d) {
        const glm::dvec4 dc = m * glm::dvec4(d, 0.0);
        return scale * (glm::dvec2(dc) * c.w - glm::dvec2(c) * dc.w) / (c.w * c.w);
    };
    return glm::dmat2(along(u), along(v));
}

} // namespace

void VirtualMapTexels::setMap(int light, const glm::mat4& lightViewProj, const PageGeometry& geometry,
                              float lodBias) {
    mLight = light;
    mShadow = FlatLightFits::textureBias() * lightViewProj;
    mGeometry = geometry;
    mLodBias = lodBias;
}

void VirtualMapTexels::setCamera(const glm::mat4& viewProj, glm::ivec2 size) {
    mCamera = viewProj;
    mSize = size;
}

int VirtualMapTexels::level(const ShadedPoint& at) const {
    if (glm::dot(at.normal, at.normal) == 0.0) return 0;
    const glm::dvec3 n = glm::normalize(at.normal);
    const glm::dvec3 u = glm::normalize(glm::cross(n, glm::dvec3(anyPerpendicularUp(glm::vec3(n)))));
    const glm::dvec3 v = glm::cross(n, u);
    const glm::dmat2 screen = projectedJacobian(mCamera, 0.5 * glm::dvec2(mSize), at.position, u, v);
    if (!(std::abs(glm::determinant(screen)) > 0.0)) return 0;
    const glm::dmat2 map =
        projectedJacobian(mShadow, glm::dvec2(double(mGeometry.virtualResolution())), at.position, u, v);
    // Map texels per screen pixel: the map's derivatives along the plane times the plane's per pixel.
    const glm::dmat2 perPixel = map * glm::inverse(screen);
    const double texelsPerPixel = std::max(glm::length(perPixel[0]), glm::length(perPixel[1]));
    if (!(texelsPerPixel > 0.0) || !std::isfinite(texelsPerPixel)) return 0;
    const double lod = std::log2(texelsPerPixel) + double(mLodBias);
    return std::clamp(int(std::floor(lod)), 0, mGeometry.levels() - 1);
}

std::optional<MapPoint> VirtualMapTexels::texel(size_t light, const ShadedPoint& at,
                                                const glm::dvec3& q) const {
    if (mLight < 0 || light != size_t(mLight) || !looksUp(mShadow, at.position)) return std::nullopt;
    const int l = level(at);
    const int resolution = mGeometry.levelResolution(l);
    return MapPoint{l, resolution, projectedTexel(mShadow, resolution, q)};
}

} // namespace sb
