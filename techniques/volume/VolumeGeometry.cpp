#include "techniques/volume/VolumeGeometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace sb {

namespace {

/// Row `r` of a column-major glm matrix.
glm::vec4 row(const glm::mat4& m, int r) {
    return {m[0][r], m[1][r], m[2][r], m[3][r]};
}

/// The plane through `point` with normal `n`, flipped so that `inside` is on its positive side, unit
/// normal. nullopt when it is not well defined: a normal that is zero relative to `scale` (the product
/// of the lengths it came from), or `inside` on the plane.
std::optional<Plane> orientedPlane(const glm::vec3& n, float scale, const glm::vec3& point,
                                   const glm::vec4& inside) {
    const float length = glm::length(n);
    // 1e-6: well above float rounding of a cross product (~1e-7 relative), far below any real angle.
    if (!(length > 1e-6f * scale)) return std::nullopt;
    Plane p(n / length, -glm::dot(n / length, point));
    const float side = glm::dot(p, inside);
    if (!(std::abs(side) > 0.0f)) return std::nullopt;
    return side > 0.0f ? p : -p;
}

/// Pixel coordinates of a clip-space point with w > 0 on a width x height viewport.
glm::vec2 toPixels(const glm::vec4& clip, int width, int height) {
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    return (ndc * 0.5f + 0.5f) * glm::vec2(float(width), float(height));
}

/// Signed distance-like value of a clip-space point to the near plane: >= 0 in front (z >= -w).
float nearSide(const glm::vec4& clip) {
    return clip.w + clip.z;
}

/// The light's range cube, world space.
Aabb rangeCube(const Light& light) {
    return {light.position - glm::vec3(light.range), light.position + glm::vec3(light.range)};
}

} // namespace

glm::mat4 VolumeGeometry::infinitePerspective(float fovYRadians, float aspect, float nearZ, float epsilon) {
    // glm::perspective's z row is (-(f + n) / (f - n), -2 f n / (f - n)) -> (-1, -2 n) as f -> inf; the
    // guard scales c by (1 - epsilon) and moves d so the near plane still maps to -1:
    // z_ndc(-n) = (-(eps - 1) n + (eps - 2) n) / n = -1, and a point at infinity has z/w = 1 - eps < 1.
    const float f = 1.0f / std::tan(0.5f * fovYRadians);
    glm::mat4 m(0.0f);
    m[0][0] = f / aspect;
    m[1][1] = f;
    m[2][2] = epsilon - 1.0f;
    m[2][3] = -1.0f;
    m[3][2] = (epsilon - 2.0f) * nearZ;
    return m;
}

std::array<Plane, 5> VolumeGeometry::frustumPlanes(const glm::mat4& viewProj) {
    // Gribb and Hartmann: a world point is inside -w <= x, y, z (clip) and x, y <= w, each a row
    // combination dotted with the homogeneous point. Order: left, right, bottom, top, near.
    const glm::vec4 r0 = row(viewProj, 0), r1 = row(viewProj, 1), r2 = row(viewProj, 2),
                    r3 = row(viewProj, 3);
    std::array<Plane, 5> planes = {r3 + r0, r3 - r0, r3 + r1, r3 - r1, r3 + r2};
    for (Plane& p : planes) {
        const float length = glm::length(glm::vec3(p));
        if (length > 0.0f) p /= length;
    }
    return planes;
}

bool VolumeGeometry::outsideAny(const std::array<Plane, 5>& planes, const glm::vec4* points, int count) {
    for (const Plane& plane : planes) {
        bool allOutside = count > 0;
        for (int i = 0; i < count && allOutside; ++i) allOutside = glm::dot(plane, points[i]) < 0.0f;
        if (allOutside) return true;
    }
    return false;
}

std::array<glm::vec4, 8> VolumeGeometry::corners(const Aabb& box) {
    std::array<glm::vec4, 8> c;
    const std::array<glm::vec3, 8> p = box.corners();
    for (size_t i = 0; i < 8; ++i) c[i] = glm::vec4(p[i], 1.0f);
    return c;
}

std::array<glm::vec4, 8> VolumeGeometry::cornersAtInfinity(const Aabb& box, const glm::vec4& light) {
    // Listing 9-3 applied to the corners: away from the light; for w = 0 all of them are -L.
    std::array<glm::vec4, 8> c = corners(box);
    for (glm::vec4& p : c) p = glm::vec4(glm::vec3(p) * light.w - glm::vec3(light), 0.0f);
    return c;
}

VolumeGeometry::CapCull VolumeGeometry::cullVolume(const std::array<Plane, 5>& frustum,
                                                   const Aabb& casterBounds, const glm::vec4& light) {
    // The light cap lies on the caster, inside its box; the dark cap is that box sent to infinity. A
    // side point is (v, 1) + t (v L.w - L.xyz, 0), t >= 0, with v in the box: a non-negative
    // combination of the two corner sets, so a plane all 16 are outside of has the sides outside too.
    std::array<glm::vec4, 16> points;
    const std::array<glm::vec4, 8> finite = corners(casterBounds),
                                   infinite = cornersAtInfinity(casterBounds, light);
    std::copy(finite.begin(), finite.end(), points.begin());
    std::copy(infinite.begin(), infinite.end(), points.begin() + 8);
    CapCull cull;
    cull.lightCap = outsideAny(frustum, finite.data(), 8);
    cull.darkCap = outsideAny(frustum, infinite.data(), 8);
    cull.sides = outsideAny(frustum, points.data(), 16);
    return cull;
}

bool VolumeGeometry::mayShadowViewport(const std::array<glm::vec3, 4>& nearRect, const glm::vec4& light,
                                       const Aabb& casterBounds) {
    // Section 9.5.4: a near-plane point is shadowed only if the segment from it to the light (a ray
    // along L.xyz for a directional light) crosses the caster; those segments fill the occlusion
    // pyramid. A box outside one of the pyramid's face planes cannot meet it (the converse does not
    // hold: true is conservative).
    const glm::vec3 centre = 0.25f * (nearRect[0] + nearRect[1] + nearRect[2] + nearRect[3]);
    const float size = glm::length(nearRect[2] - nearRect[0]);
    std::array<Plane, 5> planes;
    const bool directional = light.w == 0.0f;
    const glm::vec3 apex = directional ? glm::vec3(0.0f) : glm::vec3(light) / light.w;
    const glm::vec3 toward = directional ? glm::vec3(light) : apex - centre;
    // A point strictly inside the pyramid: the centroid of the apex and the 4 corners; for a directional
    // light, the rectangle's centre moved along L (towards the light).
    const glm::vec4 inside = directional ? glm::vec4(centre + glm::vec3(light), 1.0f)
                                         : glm::vec4((4.0f * centre + apex) / 5.0f, 1.0f);
    const float towardLength = glm::length(toward);
    for (int i = 0; i < 4; ++i) {
        const glm::vec3& a = nearRect[size_t(i)];
        const glm::vec3& b = nearRect[size_t((i + 1) % 4)];
        // The side through edge a b and the apex, or containing the direction L for a directional light.
        const glm::vec3 n = directional ? glm::cross(b - a, toward) : glm::cross(a - apex, b - apex);
        const float scale =
            directional ? glm::length(b - a) * towardLength : glm::length(a - apex) * glm::length(b - apex);
        const std::optional<Plane> p = orientedPlane(n, scale, a, inside);
        if (!p) return true; // degenerate pyramid: cannot tell
        planes[size_t(i)] = *p;
    }
    const glm::vec3 n = glm::cross(nearRect[1] - nearRect[0], nearRect[3] - nearRect[0]);
    const std::optional<Plane> base = orientedPlane(n, size * size, centre, inside);
    if (!base) return true;
    // The light in (or, for a direction, parallel to) the rectangle's plane: the pyramid is flat.
    if (std::abs(glm::dot(glm::vec3(*base), toward)) <= 1e-6f * towardLength) return true;
    planes[4] = *base;
    const std::array<glm::vec4, 8> c = corners(casterBounds);
    return !outsideAny(planes, c.data(), 8);
}

std::array<glm::vec3, 4> VolumeGeometry::nearRectangle(const glm::mat4& viewProj) {
    const glm::mat4 inverse = glm::inverse(viewProj);
    const glm::vec2 ndc[4] = {{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}};
    std::array<glm::vec3, 4> out;
    for (size_t i = 0; i < 4; ++i) {
        const glm::vec4 p = inverse * glm::vec4(ndc[i], -1.0f, 1.0f);
        out[i] = glm::vec3(p) / p.w;
    }
    return out;
}

bool VolumeGeometry::lightReaches(const Light& light, const Aabb& worldBounds) {
    if (light.type == LightType::Directional || light.range <= 0.0f) return true;
    if (worldBounds.empty()) return false; // nothing there to reach
    // Range sphere against the box: the box's point closest to the light.
    const glm::vec3 closest = glm::clamp(light.position, worldBounds.min, worldBounds.max);
    if (glm::length(closest - light.position) > light.range) return false;
    if (light.type != LightType::Spot) return true;
    // Spot cone against the box's bounding sphere (radius r at distance d from the apex): the sphere
    // subtends asin(r / d) around its centre's direction, so it misses the cone when that direction's
    // angle to the axis exceeds the outer angle by more. An apex inside the sphere sees all directions.
    const glm::vec3 toCentre = worldBounds.center() - light.position;
    const float d = glm::length(toCentre), r = 0.5f * glm::length(worldBounds.extent());
    if (d <= r) return true;
    const float cosAngle = glm::dot(toCentre / d, glm::normalize(light.direction));
    const float angle = std::acos(std::clamp(cosAngle, -1.0f, 1.0f));
    return angle - std::asin(r / d) <= glm::radians(light.spotOuterDeg);
}

std::optional<glm::ivec4> VolumeGeometry::scissorRect(const Light& light, const glm::mat4& viewProj,
                                                      int width, int height) {
    if (light.range <= 0.0f) return glm::ivec4(0, 0, width, height);
    // Section 9.6.2: the cube clipped to the near plane is a convex polyhedron whose vertices are the
    // cube's kept corners and the points where its edges cross the near plane; its projection is
    // bounded by theirs. The other frustum planes are left to the clamp to the viewport.
    std::array<glm::vec4, 8> clip = corners(rangeCube(light));
    for (glm::vec4& c : clip) c = viewProj * c;
    glm::vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    bool any = false;
    auto keep = [&](const glm::vec4& c) {
        if (c.w <= 0.0f) return; // on or behind the eye plane: no projection (only degenerate cases)
        const glm::vec2 p = toPixels(c, width, height);
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
        any = true;
    };
    for (const glm::vec4& c : clip)
        if (nearSide(c) >= 0.0f) keep(c);
    // The 12 edges: corner pairs differing in one bit.
    for (int i = 0; i < 8; ++i)
        for (int bit = 1; bit < 8; bit <<= 1) {
            if (i & bit) continue;
            const glm::vec4 &a = clip[size_t(i)], &b = clip[size_t(i | bit)];
            const float da = nearSide(a), db = nearSide(b);
            if ((da < 0.0f) != (db < 0.0f)) keep(a + (da / (da - db)) * (b - a));
        }
    if (!any) return std::nullopt;
    const int x0 = std::max(0, int(std::floor(lo.x))), y0 = std::max(0, int(std::floor(lo.y)));
    const int x1 = std::min(width, int(std::ceil(hi.x))), y1 = std::min(height, int(std::ceil(hi.y)));
    if (x1 <= x0 || y1 <= y0) return std::nullopt;
    return glm::ivec4(x0, y0, x1 - x0, y1 - y0);
}

std::optional<glm::vec2> VolumeGeometry::depthBounds(const Light& light, const glm::mat4& view,
                                                     const glm::mat4& proj) {
    if (light.range <= 0.0f) return std::nullopt;
    // Window depth grows with the distance along the view axis, which is linear over the cube: its
    // extremes are at corners. A corner in front of the near plane gives its depth; one behind it
    // means the cube reaches the near plane, depth 0.
    const glm::mat4 viewProj = proj * view;
    float zMin = 1.0f, zMax = 0.0f;
    for (const glm::vec4& corner : corners(rangeCube(light))) {
        const glm::vec4 c = viewProj * corner;
        if (nearSide(c) < 0.0f || c.w <= 0.0f) {
            zMin = 0.0f;
            continue;
        }
        const float z = std::clamp(c.z / c.w * 0.5f + 0.5f, 0.0f, 1.0f);
        zMin = std::min(zMin, z);
        zMax = std::max(zMax, z);
    }
    // Every corner behind the near plane: nothing visible is in range, [0, 0] (the caller's scissor
    // test has normally skipped such a light already).
    return glm::vec2(zMin, std::max(zMin, zMax));
}

float VolumeGeometry::boundedExtrusion(const Aabb& scene, const Aabb& caster, const glm::vec3& dir,
                                       float margin) {
    float length = std::numeric_limits<float>::max();
    for (int i = 0; i < 3; ++i) {
        if (dir[i] == 0.0f) continue; // never leaves through this slab
        // (bound - X_i) / dir_i is largest at the caster corner farthest back along dir.
        const float bound = dir[i] > 0.0f ? scene.max[i] : scene.min[i];
        const float from = dir[i] > 0.0f ? caster.min[i] : caster.max[i];
        length = std::min(length, (bound - from) / dir[i]);
    }
    if (length == std::numeric_limits<float>::max()) return 0.0f;
    // Plus 1e-4 of the scene's size, so a caster resting on the receiver still gets a volume.
    return std::max(length, 0.0f) * (1.0f + margin) + 1e-4f * glm::length(scene.extent());
}

} // namespace sb
