#include "techniques/common/InstanceCulling.h"

#include "scenes/Math.h"

namespace sb {

void InstanceCulling::setScene(const Scene& scene) {
    mScene = &scene;
    mBounds.clear();
    mSetCount.fill(0);
    for (const Instance& inst : scene.instances) {
        mBounds.push_back(inst.mesh < scene.meshes.size()
                              ? transformBounds(scene.meshes[inst.mesh].computeBounds(), inst.model)
                              : Aabb{});
        for (size_t s = 0; s < kDrawSetCount; ++s) mSetCount[s] += Submitter::inSet(inst, DrawSet(s)) ? 1 : 0;
    }
}

bool InstanceCulling::mayReach(const Aabb& box, const glm::mat4& viewProj, CullPlanes planes) {
    if (box.empty()) return false;
    // Clip-space planes: -w <= x, y, z <= w. Bit k set = the corner is outside plane k
    // (0: x < -w, 1: x > w, 2: y < -w, 3: y > w, 4: z > w (far), 5: z < -w (near)). A box is culled
    // when one bit is set for all its corners.
    unsigned allOutside = planes == CullPlanes::All ? 0x3fu : 0x1fu;
    for (const glm::vec3& c : box.corners()) {
        const glm::vec4 p = viewProj * glm::vec4(c, 1.0f);
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

size_t InstanceCulling::cull(const glm::mat4& viewProj, DrawSet set, CullPlanes planes,
                             std::vector<uint8_t>& keep) const {
    keep.assign(mBounds.size(), 0);
    size_t kept = 0;
    for (size_t i = 0; i < mBounds.size(); ++i) {
        if (!Submitter::inSet(mScene->instances[i], set) || !mayReach(mBounds[i], viewProj, planes)) continue;
        keep[i] = 1;
        ++kept;
    }
    return kept;
}

} // namespace sb
