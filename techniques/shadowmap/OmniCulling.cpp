#include "techniques/shadowmap/OmniCulling.h"

#include <algorithm>

#include "scenes/Math.h"
#include "techniques/shadowmap/PointLightFit.h"

namespace sb {

namespace {
bool whollyBehind(const Aabb& box, const glm::vec3& centre, const glm::vec3& axis) {
    for (const glm::vec3& c : box.corners())
        if (glm::dot(c - centre, axis) >= 0.0f) return false;
    return true;
}
} // namespace

void OmniCulling::setScene(const Scene& scene) {
    mBounds.clear();
    mCasts.clear();
    for (const Instance& inst : scene.instances) {
        const bool valid = inst.mesh < scene.meshes.size();
        mBounds.push_back(valid ? transformBounds(scene.meshBoundsOf(inst.mesh), inst.model) : Aabb{});
        mCasts.push_back(valid && inst.castsShadow ? 1 : 0);
    }
    mCasters = size_t(std::count(mCasts.begin(), mCasts.end(), uint8_t(1)));
}

size_t OmniCulling::cullSphere(const glm::vec3& centre, float radius, std::vector<uint8_t>& keep) const {
    keep.assign(mBounds.size(), 0);
    size_t kept = 0;
    for (size_t i = 0; i < mBounds.size(); ++i) {
        if (!mCasts[i] || PointLightFit::distanceToBox(centre, mBounds[i]) >= radius) continue;
        keep[i] = 1;
        ++kept;
    }
    return kept;
}

size_t OmniCulling::cullHemisphere(const glm::vec3& centre, float radius, const glm::vec3& axis,
                                   std::vector<uint8_t>& keep) const {
    size_t kept = cullSphere(centre, radius, keep);
    for (size_t i = 0; i < mBounds.size(); ++i)
        if (keep[i] && whollyBehind(mBounds[i], centre, axis)) {
            keep[i] = 0;
            --kept;
        }
    return kept;
}

} // namespace sb
