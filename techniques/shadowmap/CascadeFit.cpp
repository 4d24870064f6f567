#include "techniques/shadowmap/CascadeFit.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "scenes/Math.h"

namespace sb {

namespace {
/// Largest squared distance from `c` to the points.
double maxDistance2(const glm::dvec3& c, const std::array<glm::dvec3, 8>& points) {
    double m = 0.0;
    for (const glm::dvec3& p : points) {
        const glm::dvec3 d = p - c;
        m = std::max(m, glm::dot(d, d));
    }
    return m;
}

/// The slice's 8 corners in view space: 4 at d0, then 4 at d1.
std::array<glm::dvec3, 8> sliceCornersView(const glm::mat4& proj, float d0, float d1) {
    std::array<glm::dvec3, 8> out;
    const auto a = CascadeFit::viewCorners(proj, d0), b = CascadeFit::viewCorners(proj, d1);
    std::copy(a.begin(), a.end(), out.begin());
    std::copy(b.begin(), b.end(), out.begin() + 4);
    return out;
}

/// The far end of the box may not come nearer to the light than its near end.
float keepThick(float nearDepth, float farDepth) {
    return std::max(farDepth, nearDepth + 1e-4f * std::max(1.0f, std::abs(nearDepth)));
}
} // namespace

glm::mat4 CascadeFit::lightView(const glm::vec3& direction) {
    const glm::vec3 d = glm::normalize(direction);
    return glm::lookAt(glm::vec3(0.0f), d, anyPerpendicularUp(d));
}

std::array<glm::dvec3, 4> CascadeFit::viewCorners(const glm::mat4& proj, float depth) {
    // clip = P * (x, y, -depth, 1); ndc = clip / clip.w. P has no x-y coupling (perspective, ortho and
    // an NDC translation), so x and y solve independently.
    const double d = depth;
    const double w = -double(proj[2][3]) * d + double(proj[3][3]);
    std::array<glm::dvec3, 4> out;
    for (int i = 0; i < 4; ++i) {
        const double xn = (i & 1) ? 1.0 : -1.0, yn = (i & 2) ? 1.0 : -1.0;
        const double x = (xn * w + double(proj[2][0]) * d - double(proj[3][0])) / double(proj[0][0]);
        const double y = (yn * w + double(proj[2][1]) * d - double(proj[3][1])) / double(proj[1][1]);
        out[size_t(i)] = {x, y, -d};
    }
    return out;
}

glm::dvec4 CascadeFit::sliceSphere(const glm::mat4& proj, float d0, float d1) {
    const std::array<glm::dvec3, 8> corners = sliceCornersView(proj, d0, d1);
    glm::dvec3 c0(0.0), c1(0.0);
    for (int i = 0; i < 4; ++i) {
        c0 += 0.25 * corners[size_t(i)];
        c1 += 0.25 * corners[size_t(i) + 4];
    }
    // The largest distance along the segment is a maximum of convex quadratics: convex, so a ternary
    // search finds its minimum.
    double lo = 0.0, hi = 1.0;
    for (int k = 0; k < 100; ++k) {
        const double m1 = lo + (hi - lo) / 3.0, m2 = hi - (hi - lo) / 3.0;
        if (maxDistance2(c0 + m1 * (c1 - c0), corners) < maxDistance2(c0 + m2 * (c1 - c0), corners))
            hi = m2;
        else
            lo = m1;
    }
    const glm::dvec3 centre = c0 + 0.5 * (lo + hi) * (c1 - c0);
    return {centre, std::sqrt(maxDistance2(centre, corners))};
}

double CascadeFit::roundRadius(double r) {
    if (!(r > 0.0)) return 1e-6;
    const double step = std::ldexp(1.0, std::ilogb(r) - 5);
    return std::ceil(r / step) * step;
}

CascadeSceneBounds CascadeFit::sceneBounds(const Aabb& casters, const Aabb& all, const glm::mat4& lightView) {
    CascadeSceneBounds b;
    b.castersMin = glm::vec2(FLT_MAX);
    b.castersMax = glm::vec2(-FLT_MAX);
    b.castersNear = FLT_MAX;
    b.sceneFar = -FLT_MAX;
    if (!casters.empty())
        for (const glm::vec3& corner : casters.corners()) {
            const glm::vec3 q = glm::vec3(lightView * glm::vec4(corner, 1.0f));
            b.castersMin = glm::min(b.castersMin, glm::vec2(q));
            b.castersMax = glm::max(b.castersMax, glm::vec2(q));
            b.castersNear = std::min(b.castersNear, -q.z);
        }
    if (!all.empty())
        for (const glm::vec3& corner : all.corners())
            b.sceneFar = std::max(b.sceneFar, -(lightView * glm::vec4(corner, 1.0f)).z);
    if (b.castersMin.x <= b.castersMax.x) { // rounding of the corners' transform: a little room
        const glm::vec2 pad = 0.005f * (b.castersMax - b.castersMin) + glm::vec2(1e-4f);
        b.castersMin -= pad;
        b.castersMax += pad;
    }
    return b;
}

namespace {
/// The stable box's centre on one axis: the sphere's centre `s`, kept so that the box [c - h, c + h]
/// snapped down by less than a texel t still covers what the casters' range [lo, hi] needs of it.
double clampToCasters(double s, double h, double t, float lo, float hi) {
    if (lo > hi) return s; // no casters: nothing to clamp to
    const double from = double(lo) + h, to = double(hi) - h + t;
    if (from > to) return 0.5 * (double(lo) + double(hi)) + 0.5 * t; // the box holds them whole
    return std::clamp(s, from, to);
}
} // namespace

Cascade CascadeFit::fit(const glm::mat4& lightView, const glm::mat4& view, const glm::mat4& proj, float d0,
                        float d1, const CascadeSceneBounds& bounds, int resolution, bool stabilize) {
    Cascade c;
    c.lightView = lightView;
    const glm::dmat4 viewToLight = glm::dmat4(lightView) * glm::inverse(glm::dmat4(view));
    const double margin = double(resolution) / double(resolution - 2); // one texel each side
    const bool haveCasters = bounds.castersMin.x <= bounds.castersMax.x;
    glm::dvec2 lo, hi;
    double nearDepth, farDepth;
    if (stabilize) {
        const glm::dvec4 sphere = sliceSphere(proj, d0, d1);
        const glm::dvec3 centre = glm::dvec3(viewToLight * glm::dvec4(glm::dvec3(sphere), 1.0));
        const double hs = roundRadius(sphere.w) * margin;
        const glm::dvec2 castersHalf = 0.5 * glm::dvec2(bounds.castersMax - bounds.castersMin);
        const double h = haveCasters ? std::min(hs, std::max(castersHalf.x, castersHalf.y) * margin) : hs;
        const double t = 2.0 * h / double(resolution);
        glm::dvec3 kept = centre;
        for (int a = 0; a < 2; ++a)
            kept[a] = clampToCasters(centre[a], h, t, bounds.castersMin[a], bounds.castersMax[a]);
        const glm::dvec3 snapped = glm::floor(kept / t) * t;
        c.unsnappedCentre = glm::vec3(centre);
        c.centre = glm::vec3(snapped);
        c.halfExtent = float(h);
        c.texel = float(t);
        lo = glm::dvec2(snapped) - h;
        hi = glm::dvec2(snapped) + h;
        nearDepth = -snapped.z - hs; // light-frame z is minus the depth; the sphere's whole depth
        farDepth = -snapped.z + hs;
    } else {
        glm::dvec3 a(DBL_MAX), b(-DBL_MAX);
        for (const glm::dvec3& p : sliceCornersView(proj, d0, d1)) {
            const glm::dvec3 q = glm::dvec3(viewToLight * glm::dvec4(p, 1.0));
            a = glm::min(a, q);
            b = glm::max(b, q);
        }
        lo = glm::dvec2(a);
        hi = glm::dvec2(b);
        if (haveCasters && glm::all(glm::lessThan(glm::max(lo, glm::dvec2(bounds.castersMin)),
                                                  glm::min(hi, glm::dvec2(bounds.castersMax))))) {
            lo = glm::max(lo, glm::dvec2(bounds.castersMin));
            hi = glm::min(hi, glm::dvec2(bounds.castersMax));
        }
        c.unsnappedCentre = c.centre = glm::vec3(glm::vec2(0.5 * (lo + hi)), float(0.5 * (a.z + b.z)));
        c.halfExtent = float(0.5 * std::max(hi.x - lo.x, hi.y - lo.y));
        c.texel = 2.0f * c.halfExtent / float(resolution);
        nearDepth = -b.z;
        farDepth = -a.z;
    }
    // Casters between the light and the slice still shadow it, and nothing nearer the light casts:
    // the near side is the nearest caster's depth. Nothing lies beyond the scene.
    c.nearDepth = haveCasters ? bounds.castersNear : float(nearDepth);
    c.farDepth = keepThick(c.nearDepth, std::min(float(farDepth), bounds.sceneFar));
    c.viewProj =
        glm::ortho(float(lo.x), float(hi.x), float(lo.y), float(hi.y), c.nearDepth, c.farDepth) * lightView;
    return c;
}

} // namespace sb
