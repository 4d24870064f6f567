#include "techniques/virtual/CasterFootprints.h"

#include <limits>

#include "scenes/Math.h"

namespace sb {

void CasterFootprints::reset(const Scene& scene, const glm::mat4& lightViewProj, const PageGeometry& geometry,
                             float marginTexels) {
    mLightViewProj = lightViewProj;
    mGeometry = geometry;
    mMargin = marginTexels;
    mModel.assign(scene.instances.size(), glm::mat4(1.0f));
    mPages.assign(scene.instances.size(), PageRect{});
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        mModel[i] = scene.instances[i].model;
        mPages[i] = footprint(scene, i);
    }
}

size_t CasterFootprints::moved(const Scene& scene, std::vector<PageRect>& out) {
    size_t count = 0;
    for (size_t i = 0; i < scene.instances.size() && i < mModel.size(); ++i) {
        const Instance& inst = scene.instances[i];
        if (!inst.castsShadow || inst.model == mModel[i]) continue;
        out.push_back(mPages[i]);
        mModel[i] = inst.model;
        mPages[i] = footprint(scene, i);
        out.push_back(mPages[i]);
        ++count;
    }
    return count;
}

PageRect CasterFootprints::footprint(const Scene& scene, size_t instance) const {
    const Instance& inst = scene.instances[instance];
    if (!inst.castsShadow || inst.mesh >= scene.meshes.size()) return {};
    const Aabb world = transformBounds(scene.meshBoundsOf(inst.mesh), inst.model);
    if (world.empty()) return {};
    glm::vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 corner((c & 1) ? world.max.x : world.min.x, (c & 2) ? world.max.y : world.min.y,
                               (c & 4) ? world.max.z : world.min.z);
        const glm::vec4 clip = mLightViewProj * glm::vec4(corner, 1.0f);
        // A corner behind a perspective light: the caster may cover any part of the map.
        if (clip.w <= 0.0f) return {glm::ivec2(0), glm::ivec2(mGeometry.pagesPerSide() - 1)};
        const glm::vec2 texel =
            (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * float(mGeometry.virtualResolution());
        lo = glm::min(lo, texel);
        hi = glm::max(hi, texel);
    }
    return mGeometry.pagesOfTexels(lo - mMargin, hi + mMargin);
}

} // namespace sb
