#include "techniques/virtual/PageGeometry.h"

#include <cmath>
#include <string>

#include "core/Error.h"

namespace sb {

PageGeometry::PageGeometry(int virtualResolution, int pageSize, int poolPages)
    : mVirtualResolution(virtualResolution), mPageSize(pageSize), mPoolPages(poolPages) {
    const std::string where = "virtual shadow map: ";
    if (pageSize < 8) throw Error(where + "page_size " + std::to_string(pageSize) + " is below 8 texels");
    if (virtualResolution < pageSize || virtualResolution % pageSize != 0)
        throw Error(where + "virtual_resolution " + std::to_string(virtualResolution) +
                    " is not a positive multiple of page_size " + std::to_string(pageSize));
    mPagesPerSide = virtualResolution / pageSize;
    if (poolPages < 1 || uint32_t(poolPages) > pageCount())
        throw Error(where + "pool_pages " + std::to_string(poolPages) + " is outside [1, " +
                    std::to_string(pageCount()) + "], the virtual map's page count");
    mAtlasPagesPerSide = int(std::ceil(std::sqrt(double(poolPages))));
    while (mAtlasPagesPerSide * mAtlasPagesPerSide < poolPages) ++mAtlasPagesPerSide; // sqrt's rounding
}

PageRect PageGeometry::pagesOfTexels(glm::vec2 lo, glm::vec2 hi) const {
    const float last = float(mVirtualResolution);
    // Wholly outside the map (a texel t lies in the map when 0 <= t < resolution).
    if (hi.x < 0.0f || hi.y < 0.0f || lo.x >= last || lo.y >= last) return {};
    const glm::vec2 clippedLo = glm::max(lo, glm::vec2(0.0f));
    const glm::vec2 clippedHi = glm::min(hi, glm::vec2(last - 1.0f));
    PageRect r;
    r.lo = glm::ivec2(glm::floor(clippedLo / float(mPageSize)));
    r.hi = glm::ivec2(glm::floor(clippedHi / float(mPageSize)));
    r.lo = glm::clamp(r.lo, glm::ivec2(0), glm::ivec2(mPagesPerSide - 1));
    r.hi = glm::clamp(r.hi, glm::ivec2(0), glm::ivec2(mPagesPerSide - 1));
    return r;
}

} // namespace sb
