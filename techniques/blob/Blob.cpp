#include "techniques/blob/Blob.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>

#include "shading/ShaderLimits.h"
#include "techniques/Property.h"

namespace sb {

namespace {

/// The knobs, one maker call each (techniques/Property.h): what --list shows and -t name:k=v sets.
std::vector<PropertyDesc> declareProperties() {
    return {
        real(Blob::kOpacity, "1", 0, 1, "opacity of a blob on the ground"),
        real(Blob::kSoftness, "0.5", 0, 1,
             "width of the soft edge as a fraction of the ellipse's radius (0: hard)"),
        real(Blob::kFade, "8", 0.01, 1e6,
             "height (in bounding radii) of the caster's bottom at which its blob vanishes"),
    };
}

/// How far from the light's foot (its orthogonal projection onto the plane) light reaches on the
/// plane: the circle its range cuts out (0: the plane is beyond the range) and the farthest corner of
/// the plane's rectangle (a receiver ends there). Infinite for an unlimited light over a rectangle of
/// no extent (a plane built by hand).
float reachOnPlane(const ReceiverPlane& plane, const Light& light, const glm::vec3& foot, float hl) {
    float reach = INFINITY;
    if (light.range > 0.0f) reach = hl < light.range ? std::sqrt(light.range * light.range - hl * hl) : 0.0f;
    float farthest = 0.0f;
    for (const glm::vec3& c : plane.corners) farthest = std::max(farthest, glm::distance(c, foot));
    if (farthest > 0.0f) reach = std::min(reach, farthest);
    return reach;
}

/// `p` projected onto the plane along the light: from a point light's position, along a directional
/// one. A point light lands a point at height h and distance r from its foot at r hl / (hl - h): the
/// part of a caster near the light's height casts a shadow that runs off to infinity, and a point at
/// or above that height none at all (the shadow of a caster straddling the light's height is an
/// unbounded wedge behind it). Such points are held where the light stops reaching, `reach` from the
/// foot in the point's direction (or at their own distance, when they lie beyond it already): the
/// blob covers the wedge as far as anything is lit and no further, where holding them at a fixed
/// fraction of the light's height magnified them through it over the whole lit pool. With no reach
/// known (infinite), points are held at 99% of the light's height (a magnification of 100).
glm::vec3 projectAlongLight(const glm::vec3& p, const ReceiverPlane& plane, const glm::vec4& light,
                            float reach) {
    const float h = plane.distance(p);
    if (light.w == 0.0f) { // directional: light.xyz points towards the light
        const glm::vec3 dir = -glm::vec3(light);
        return p - dir * (h / glm::dot(plane.normal, dir));
    }
    const glm::vec3 l(light);
    const float hl = plane.distance(l);
    if (!std::isfinite(reach)) {
        const float hp = std::min(h, 0.99f * hl);
        return l + (p - l) * (hl / (hl - hp));
    }
    const glm::vec3 foot = l - hl * plane.normal;
    const glm::vec3 offset = (p - h * plane.normal) - foot; // in the plane
    const float r = glm::length(offset);
    const float limit = std::max(reach, r);
    const float landed = h < hl ? r * (hl / (hl - h)) : INFINITY;
    if (landed <= limit) return foot + offset * (hl / (hl - h));
    return r > 0.0f ? foot + offset * (limit / r) : foot;
}

} // namespace

TechniqueInfo Blob::declaration() {
    return {.name = "blob",
            .description = "fake blob shadows: a soft ellipse on the ground under each caster per light, "
                           "sized from its bounds (no self-shadowing, ground plane only)",
            .effects = Effect::SoftShadows | Effect::MultipleLights,
            .capabilities = {{Api::GL, "GL 4.5", 4, 5, ""}},
            .passes = {"lighting", "blobs"},
            .properties = declareProperties(),
            .quality = {
                {kSoftness, {"0", "0.25", "0.5", "1"}},
                {kFade, {"2", "8", "32"}},
            }};
}

std::optional<ReceiverPlane> Blob::findGround(const Scene& scene) {
    std::optional<ReceiverPlane> best;
    for (const ReceiverPlane& p : ReceiverPlane::find(scene))
        if (p.normal.y >= 0.5f && (!best || p.normal.y > best->normal.y)) best = p;
    return best;
}

std::optional<ReceiverPlane> Blob::groundOf(const Scene& scene) {
    std::optional<ReceiverPlane> ground = findGround(scene);
    if (!ground)
        std::cerr << "blob: scene '" << scene.name
                  << "' has no ground plane (a planar instance facing up that receives and casts no shadow): "
                     "nothing is shadowed\n";
    return ground;
}

std::vector<Aabb> Blob::meshBounds(const Scene& scene) {
    std::vector<Aabb> bounds;
    for (size_t m = 0; m < scene.meshes.size(); ++m) bounds.push_back(scene.meshBoundsOf(m));
    return bounds;
}

std::optional<Blob::Record> Blob::fit(const Aabb& bounds, const ReceiverPlane& ground, const Light& light,
                                      int lightIndex, float opacity, float softness, float fade) {
    const glm::vec4 l = ReceiverPlane::homogeneousLight(light);
    if (bounds.empty() || !(ground.lightSide(l) > 1e-6f * std::max(1.0f, glm::length(glm::vec3(l)))))
        return std::nullopt;
    const std::array<glm::vec3, 8> c = bounds.corners();
    float hMin = INFINITY, hMax = -INFINITY;
    for (const glm::vec3& p : c) {
        hMin = std::min(hMin, ground.distance(p));
        hMax = std::max(hMax, ground.distance(p));
    }
    if (!(hMax > 0.0f)) return std::nullopt; // wholly below the ground
    float reach = INFINITY;
    if (l.w != 0.0f) {
        const float hl = ground.distance(glm::vec3(l));
        // A point light below the caster's bottom: every ray from the ground to the light passes under
        // it, so it shadows nothing (projected through the light it would cover the whole ground).
        if (hMin >= hl) return std::nullopt;
        // A shadow lies farther from the light than its caster: a caster wholly beyond the light's
        // range shadows only ground that the light does not reach.
        const glm::vec3 nearest = glm::clamp(glm::vec3(l), bounds.min, bounds.max);
        if (light.range > 0.0f && glm::distance(nearest, glm::vec3(l)) >= light.range) return std::nullopt;
        reach = reachOnPlane(ground, light, glm::vec3(l) - hl * ground.normal, hl);
        if (!(reach > 0.0f)) return std::nullopt; // the ground lies beyond the range
    }
    const float radius = 0.5f * glm::length(bounds.extent());
    const float alpha =
        opacity * std::clamp(1.0f - std::max(hMin, 0.0f) / (fade * std::max(radius, 1e-6f)), 0.0f, 1.0f);
    if (!(alpha > 0.0f)) return std::nullopt;

    // In-plane coordinates of the projected corners, then their principal axes.
    const auto [t, b] = ReceiverPlane::basis(ground.normal);
    const glm::vec3 origin = -ground.d * ground.normal;
    std::array<glm::vec2, 8> q;
    glm::vec2 mean(0.0f);
    for (size_t i = 0; i < 8; ++i) {
        const glm::vec3 p = projectAlongLight(c[i], ground, l, reach) - origin;
        q[i] = {glm::dot(p, t), glm::dot(p, b)};
        mean += q[i] / 8.0f;
    }
    float cxx = 0, cyy = 0, cxy = 0;
    for (const glm::vec2& v : q) {
        const glm::vec2 e = v - mean;
        cxx += e.x * e.x;
        cyy += e.y * e.y;
        cxy += e.x * e.y;
    }
    // Principal axes of the eight points; semi-axes sqrt(2) standard deviations, the ellipse through the
    // corners of a rectangle (a footprint [-a, a] x [-b, b] has variances a^2 and b^2). Unlike the
    // points' extent along the axes, this is continuous: a square footprint, whose axes are arbitrary,
    // gets the same circle whichever pair float rounding picks.
    cxx /= 8.0f;
    cyy /= 8.0f;
    cxy /= 8.0f;
    const float angle = 0.5f * std::atan2(2.0f * cxy, cxx - cyy);
    const glm::vec2 e1(std::cos(angle), std::sin(angle)), e2(-e1.y, e1.x);
    const float mean0 = 0.5f * (cxx + cyy), diff = std::sqrt(0.25f * (cxx - cyy) * (cxx - cyy) + cxy * cxy);
    // A degenerate axis (a flat caster seen edge-on by the light) keeps a sliver, not a zero.
    const float floor = 1e-4f * std::max(radius, 1e-6f);
    const glm::vec2 half(std::max(std::sqrt(2.0f * (mean0 + diff)), floor),
                         std::max(std::sqrt(2.0f * std::max(mean0 - diff, 0.0f)), floor));
    const glm::vec2 centre = mean;
    const glm::vec3 u = e1.x * t + e1.y * b, v = e2.x * t + e2.y * b;
    return Record{glm::vec4(origin + centre.x * t + centre.y * b, alpha),
                  glm::vec4(u * half.x, float(lightIndex)), glm::vec4(v * half.y, softness)};
}

void Blob::fitAll(const Scene& scene, const ReceiverPlane& ground, const std::vector<Aabb>& meshBounds,
                  const PropertySet& p, std::vector<Record>& out) {
    out.clear();
    const float opacity = float(p.getFloat(Blob::kOpacity)), softness = float(p.getFloat(Blob::kSoftness)),
                fade = float(p.getFloat(Blob::kFade));
    const int lights = std::min<int>(int(scene.lights.size()), kMaxLights);
    for (const Instance& inst : scene.instances) {
        if (!inst.castsShadow) continue;
        Aabb world;
        for (const glm::vec3& c : meshBounds[inst.mesh].corners())
            world.extend(glm::vec3(inst.model * glm::vec4(c, 1.0f)));
        for (int l = 0; l < lights; ++l)
            if (!scene.lights[size_t(l)].castsShadows)
                continue; // a fill light: no blob
            else if (auto blob = fit(world, ground, scene.lights[size_t(l)], l, opacity, softness, fade))
                out.push_back(*blob);
    }
}

Counters Blob::counters(const SubmitStats& s, size_t blobs) {
    // The ground's marking and the instanced blobs: two draws when there is a blob at all.
    const double extra = blobs == 0 ? 0.0 : 2.0;
    return {{"draw_calls", double(s.drawCalls) + extra},
            {"triangles", double(s.triangles) + 2.0 * double(blobs) + extra},
            {"blobs", double(blobs)}};
}

} // namespace sb
