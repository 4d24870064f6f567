#pragma once
// `virtual`'s invalidation from caster motion (NOTES-virtual.md, "Caching"): per instance that casts a
// shadow, the pages of the virtual map its world bounds cover from the light, grown by `marginTexels`
// (rasterization's rounding), and the model matrix they were computed from. A scene in motion says only
// that casters moved (Technique::sceneChanged with kCastersMoved, scenes/Motion.h), not which; moved()
// finds them by comparing each caster's model matrix with the one remembered, and hands back the pages
// whose depth it may have changed: those its old bounds covered (its shadow left them) and those its new
// bounds cover (its shadow arrived). A page no moved caster covers, before or after, keeps its depth
// bit for bit. This is UE5's rule for cached pages (Epic's documentation "Virtual Shadow Maps", "Cache
// invalidation": a moving primitive invalidates the cached pages its bounds overlap).
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/Scene.h"
#include "techniques/virtual/PageGeometry.h"

namespace sb {

class CasterFootprints {
public:
    /// Remembers every casting instance of `scene` with its pages in the map of `lightViewProj` (world ->
    /// map clip, GL conventions): the light's transform, fixed until the next reset.
    void reset(const Scene& scene, const glm::mat4& lightViewProj, const PageGeometry& geometry,
               float marginTexels);
    /// Appends to `out` the old and the new pages of every caster whose model matrix differs from the
    /// remembered one, and remembers the new. Returns how many casters moved.
    size_t moved(const Scene& scene, std::vector<PageRect>& out);
    /// The pages caster `instance` (an index into Scene::instances) covers now; empty for one that does
    /// not cast.
    PageRect pages(size_t instance) const { return mPages[instance]; }

private:
    PageRect footprint(const Scene& scene, size_t instance) const;

    glm::mat4 mLightViewProj{1.0f};
    PageGeometry mGeometry{128, 128, 1};
    float mMargin = 1.0f;
    std::vector<glm::mat4> mModel; ///< per instance, as remembered
    std::vector<PageRect> mPages;  ///< per instance (empty: not a caster)
};

} // namespace sb
