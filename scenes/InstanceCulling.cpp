#include "scenes/InstanceCulling.h"

#include <algorithm>
#include <array>
#include <limits>

#include "scenes/Math.h"

namespace sb {

void InstanceCulling::setScene(const Scene& scene) {
    mScene = &scene;
    mMeshBounds.clear();
    for (size_t m = 0; m < scene.meshes.size(); ++m) mMeshBounds.push_back(scene.meshBoundsOf(m));
    mBounds.assign(scene.instances.size(), Aabb{});
    mSetCount.fill(0);
    for (const Instance& inst : scene.instances)
        for (size_t s = 0; s < kDrawSetCount; ++s) mSetCount[s] += inDrawSet(inst, DrawSet(s)) ? 1 : 0;
    instancesMoved(scene);
}

void InstanceCulling::instancesMoved(const Scene& scene) {
    if (mMeshBounds.size() != scene.meshes.size() || mBounds.size() != scene.instances.size()) {
        setScene(scene);
        return;
    }
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& inst = scene.instances[i];
        mBounds[i] =
            inst.mesh < mMeshBounds.size() ? transformBounds(mMeshBounds[inst.mesh], inst.model) : Aabb{};
    }
}

bool InstanceCulling::mayReach(const Aabb& box, const glm::mat4& viewProj, CullPlanes planes) {
    if (box.empty()) return false;
    std::array<glm::vec4, 8> points;
    const std::array<glm::vec3, 8> corners = box.corners();
    for (size_t i = 0; i < 8; ++i) points[i] = glm::vec4(corners[i], 1.0f);
    return hullMayReach(points.data(), points.size(), viewProj, planes);
}

bool InstanceCulling::hullMayReach(const glm::vec4* points, size_t count, const glm::mat4& viewProj,
                                   CullPlanes planes) {
    // Clip-space planes: -w <= x, y, z <= w. Bit k set = the point is outside plane k
    // (0: x < -w, 1: x > w, 2: y < -w, 3: y > w, 4: z > w (far), 5: z < -w (near)). The points are
    // culled when one bit is set for all of them.
    unsigned allOutside = planes == CullPlanes::All ? 0x3fu : 0x1fu;
    for (size_t i = 0; i < count; ++i) {
        const glm::vec4 p = viewProj * points[i];
        unsigned out = 0;
        out |= p.x < -p.w ? 1u : 0u;
        out |= p.x > p.w ? 2u : 0u;
        out |= p.y < -p.w ? 4u : 0u;
        out |= p.y > p.w ? 8u : 0u;
        out |= p.z > p.w ? 16u : 0u;
        out |= p.z < -p.w ? 32u : 0u;
        allOutside &= out;
        if (!allOutside) return true;
    }
    return false;
}

bool InstanceCulling::shadowMayReach(const Aabb& box, const Light& light, const Aabb& receivers,
                                     const glm::mat4& viewProj, float margin) {
    if (box.empty()) return false;
    if (receivers.empty()) return true; // nothing known of the receivers: keep
    Aabb b = box;
    b.min -= glm::vec3(margin);
    b.max += glm::vec3(margin);
    // The shadow lies in the hull of the box and its copy moved away from the light past every
    // receiver: a directional light sweeps it by `reach` along its direction, a point or spot light
    // scales it about the light by `scale` (each point of the shadow volume is a convex combination of
    // a corner and its far copy).
    const float reach = glm::length(b.center() - receivers.center()) + glm::length(b.extent()) +
                        glm::length(receivers.extent());
    const std::array<glm::vec3, 8> corners = b.corners();
    float nearest = std::numeric_limits<float>::max();
    for (const glm::vec3& c : corners) nearest = std::min(nearest, glm::length(c - light.position));
    const bool directional = light.type == LightType::Directional;
    if (!directional && !(nearest > 0.0f)) return true; // the light inside the box: every direction
    const float scale = directional ? 1.0f : 1.0f + reach / nearest;
    const glm::vec3 towards = glm::normalize(light.direction);
    std::array<glm::vec4, 16> points;
    for (size_t k = 0; k < 8; ++k) {
        points[k] = glm::vec4(corners[k], 1.0f);
        const glm::vec3 far = directional ? corners[k] + towards * reach
                                          : light.position + scale * (corners[k] - light.position);
        points[8 + k] = glm::vec4(far, 1.0f);
    }
    return hullMayReach(points.data(), points.size(), viewProj, CullPlanes::All);
}

size_t InstanceCulling::cullShadows(const Light& light, const Aabb& receivers, const glm::mat4& viewProj,
                                    std::vector<uint8_t>& keep) const {
    keep.assign(mBounds.size(), 0);
    size_t kept = 0;
    for (size_t i = 0; i < mBounds.size(); ++i) {
        if (!mScene->instances[i].castsShadow ||
            !shadowMayReach(mBounds[i], light, receivers, viewProj, 0.0f))
            continue;
        keep[i] = 1;
        ++kept;
    }
    return kept;
}

size_t InstanceCulling::keepReachingView(const Light& light, const ViewReach& view, float margin,
                                         std::vector<uint8_t>& keep) const {
    size_t kept = 0;
    for (size_t i = 0; i < keep.size() && i < mBounds.size(); ++i) {
        if (!keep[i]) continue;
        if (shadowMayReach(mBounds[i], light, view.receivers, view.camera, margin))
            ++kept;
        else
            keep[i] = 0;
    }
    return kept;
}

size_t InstanceCulling::cullFlattened(const glm::mat4& flatten, const glm::mat4& viewProj, bool divided,
                                      std::vector<uint8_t>& keep) const {
    keep.assign(mBounds.size(), 0);
    size_t kept = 0;
    for (size_t i = 0; i < mBounds.size(); ++i) {
        if (!mScene->instances[i].castsShadow || mBounds[i].empty()) continue;
        std::array<glm::vec4, 8> points;
        const std::array<glm::vec3, 8> corners = mBounds[i].corners();
        bool beyondLight = false;
        for (size_t k = 0; k < 8; ++k) {
            points[k] = flatten * glm::vec4(corners[k], 1.0f);
            beyondLight = beyondLight || !(points[k].w > 0.0f);
            if (divided && points[k].w > 0.0f)
                points[k] = glm::vec4(glm::vec3(points[k]) / points[k].w, 1.0f);
        }
        if (!(divided && beyondLight) &&
            !hullMayReach(points.data(), points.size(), viewProj, CullPlanes::All))
            continue;
        keep[i] = 1;
        ++kept;
    }
    return kept;
}

size_t InstanceCulling::cull(const glm::mat4& viewProj, DrawSet set, CullPlanes planes,
                             std::vector<uint8_t>& keep) const {
    keep.assign(mBounds.size(), 0);
    size_t kept = 0;
    for (size_t i = 0; i < mBounds.size(); ++i) {
        if (!inDrawSet(mScene->instances[i], set) || !mayReach(mBounds[i], viewProj, planes)) continue;
        keep[i] = 1;
        ++kept;
    }
    return kept;
}

} // namespace sb
