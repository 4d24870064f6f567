#include "techniques/virtual/PageMarking.h"

namespace sb {

PageMarking::PageMarking(const PageGeometry& geometry, float footprintTexels)
    : mGeometry(geometry), mFootprint(footprintTexels) {}

PageRect PageMarking::pagesOf(const glm::mat4& lightViewProj, const glm::vec3& p, int level) const {
    const glm::vec4 clip = lightViewProj * glm::vec4(p, 1.0f);
    if (clip.w <= 0.0f) return {};
    const glm::vec2 texel =
        (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * float(mGeometry.levelResolution(level));
    return mGeometry.pagesOfTexels(texel - mFootprint, texel + mFootprint, level);
}

void PageMarking::mark(const glm::mat4& lightViewProj, const glm::vec3& p, std::vector<uint8_t>& needed,
                       int level) const {
    const PageRect r = pagesOf(lightViewProj, p, level);
    for (int y = r.lo.y; y <= r.hi.y; ++y)
        for (int x = r.lo.x; x <= r.hi.x; ++x) needed[mGeometry.pageIndex(level, {x, y})] = 1;
}

} // namespace sb
