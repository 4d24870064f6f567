#include "techniques/shadowmap/ParaboloidSplitting.h"

#include <algorithm>
#include <cmath>

#include "scenes/Math.h"
#include "techniques/shadowmap/PointLightFit.h"

namespace sb {

namespace {

float longestEdge(const Mesh& mesh) {
    float longest = 0.0f;
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
        for (int e = 0; e < 3; ++e) {
            const glm::vec3& p = mesh.positions[mesh.indices[t + e]];
            const glm::vec3& q = mesh.positions[mesh.indices[t + (e + 1) % 3]];
            longest = std::max(longest, glm::length(p - q));
        }
    return longest;
}

// For M = T R S the columns of the upper 3x3 are R's scaled by S: their largest length is the most
// any direction is stretched.
float largestScale(const glm::mat4& m) {
    return std::max(
        {glm::length(glm::vec3(m[0])), glm::length(glm::vec3(m[1])), glm::length(glm::vec3(m[2]))});
}

} // namespace

float ParaboloidSplitting::maxSegmentAngle(int resolution) {
    return std::sqrt(16.0f * kMaxSagittaTexels / float(std::max(resolution, 1)));
}

void ParaboloidSplitting::setScene(const Scene& scene) {
    // A scene in motion calls this every frame; its meshes stay, only the instances move.
    if (mMeshLongestEdge.size() != scene.meshes.size()) {
        mMeshLongestEdge.clear();
        for (const Mesh& mesh : scene.meshes) mMeshLongestEdge.push_back(longestEdge(mesh));
    }
    mBounds.clear();
    mLongestEdge.clear();
    for (const Instance& inst : scene.instances) {
        const bool valid = inst.mesh < scene.meshes.size();
        mBounds.push_back(valid ? transformBounds(scene.meshBoundsOf(inst.mesh), inst.model) : Aabb{});
        mLongestEdge.push_back(valid ? mMeshLongestEdge[inst.mesh] * largestScale(inst.model) : 0.0f);
    }
}

float ParaboloidSplitting::widestEdgeAngle(size_t i, const glm::vec3& light) const {
    const float d = PointLightFit::distanceToBox(light, mBounds[i]);
    if (d <= 0.0f) return float(M_PI);
    return 2.0f * std::atan(mLongestEdge[i] / (2.0f * d));
}

size_t ParaboloidSplitting::partition(const glm::vec3& light, float maxAngle,
                                      const std::vector<uint8_t>& keep, std::vector<uint8_t>& plain,
                                      std::vector<uint8_t>& split) const {
    plain.assign(keep.size(), 0);
    split.assign(keep.size(), 0);
    size_t splitCount = 0;
    for (size_t i = 0; i < keep.size() && i < mBounds.size(); ++i) {
        if (!keep[i]) continue;
        const bool wide = widestEdgeAngle(i, light) > maxAngle;
        (wide ? split : plain)[i] = 1;
        splitCount += wide ? 1 : 0;
    }
    return splitCount;
}

} // namespace sb
