#include "techniques/virtual/PageGeometry.h"

#include <cmath>
#include <string>

#include "core/Error.h"

namespace sb {

int PageGeometry::maxLevels(int virtualResolution, int pageSize) {
    if (pageSize < 1 || virtualResolution < pageSize || virtualResolution % pageSize != 0) return 0;
    int levels = 1;
    for (int side = virtualResolution / pageSize; side % 2 == 0; side /= 2) ++levels;
    return levels;
}

PageGeometry::PageGeometry(int virtualResolution, int pageSize, int poolPages, int levels)
    : mVirtualResolution(virtualResolution), mPageSize(pageSize), mLevels(levels), mPoolPages(poolPages) {
    const std::string where = "virtual shadow map: ";
    if (pageSize < 8) throw Error(where + "page_size " + std::to_string(pageSize) + " is below 8 texels");
    if (virtualResolution < pageSize || virtualResolution % pageSize != 0)
        throw Error(where + "virtual_resolution " + std::to_string(virtualResolution) +
                    " is not a positive multiple of page_size " + std::to_string(pageSize));
    mPagesPerSide = virtualResolution / pageSize;
    const int most = maxLevels(virtualResolution, pageSize);
    if (levels < 1 || levels > most)
        throw Error(where + "levels " + std::to_string(levels) + " is outside [1, " + std::to_string(most) +
                    "]: each level halves the " + std::to_string(mPagesPerSide) + " pages a side");
    mLevelOffset.assign(1, 0u);
    for (int l = 0; l < levels; ++l)
        mLevelOffset.push_back(mLevelOffset.back() + uint32_t(pagesPerSide(l)) * uint32_t(pagesPerSide(l)));
    if (poolPages < 1 || uint32_t(poolPages) > pageCount())
        throw Error(where + "pool_pages " + std::to_string(poolPages) + " is outside [1, " +
                    std::to_string(pageCount()) + "], the virtual map's page count");
    mAtlasPagesPerSide = int(std::ceil(std::sqrt(double(poolPages))));
    while (mAtlasPagesPerSide * mAtlasPagesPerSide < poolPages) ++mAtlasPagesPerSide; // sqrt's rounding
}

PageAddress PageGeometry::address(uint32_t page) const {
    int level = 0;
    while (level + 1 < mLevels && page >= levelOffset(level + 1)) ++level;
    const uint32_t i = page - levelOffset(level);
    const uint32_t side = uint32_t(pagesPerSide(level));
    return {level, glm::ivec2(int(i % side), int(i / side))};
}

PageRect PageGeometry::pagesOfTexels(glm::vec2 lo, glm::vec2 hi, int level) const {
    const float last = float(levelResolution(level));
    // Wholly outside the map (a texel t lies in the map when 0 <= t < resolution).
    if (hi.x < 0.0f || hi.y < 0.0f || lo.x >= last || lo.y >= last) return {};
    const glm::vec2 clippedLo = glm::max(lo, glm::vec2(0.0f));
    const glm::vec2 clippedHi = glm::min(hi, glm::vec2(last - 1.0f));
    PageRect r;
    r.lo = glm::ivec2(glm::floor(clippedLo / float(mPageSize)));
    r.hi = glm::ivec2(glm::floor(clippedHi / float(mPageSize)));
    r.lo = glm::clamp(r.lo, glm::ivec2(0), glm::ivec2(pagesPerSide(level) - 1));
    r.hi = glm::clamp(r.hi, glm::ivec2(0), glm::ivec2(pagesPerSide(level) - 1));
    return r;
}

} // namespace sb
