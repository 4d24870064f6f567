#pragma once
// `virtual`'s sizes (NOTES-virtual.md, "Data structures"): a square virtual shadow map of
// `virtualResolution` texels cut into square pages of `pageSize` texels (Epic's UE5 documentation,
// "Virtual Shadow Maps": a 16k^2 virtual map in 128^2 pages), and the physical pool that backs the pages
// in use: `poolPages` page slots laid out as a square 2D atlas texture, slot s at column s mod side and
// row s / side. Pages are numbered row-major over the virtual map (page (x, y) is y * pagesPerSide + x),
// the numbering the GPU's page table uses too (one word per page, PageTable::packed).
#include <cstdint>

#include <glm/glm.hpp>

namespace sb {

/// An inclusive rectangle of pages (lo <= hi on both axes), or empty.
struct PageRect {
    glm::ivec2 lo{0};
    glm::ivec2 hi{-1};
    bool empty() const { return hi.x < lo.x || hi.y < lo.y; }
    uint32_t count() const { return empty() ? 0u : uint32_t((hi.x - lo.x + 1) * (hi.y - lo.y + 1)); }
};

class PageGeometry {
public:
    /// Throws sb::Error (ExitCode::BadInput) naming the value when `pageSize` is below 8,
    /// `virtualResolution` is not a positive multiple of it, or `poolPages` is below 1 or above the
    /// virtual map's page count (a larger pool could never be filled).
    PageGeometry(int virtualResolution, int pageSize, int poolPages);

    int virtualResolution() const { return mVirtualResolution; }
    int pageSize() const { return mPageSize; }
    int pagesPerSide() const { return mPagesPerSide; }
    uint32_t pageCount() const { return uint32_t(mPagesPerSide) * uint32_t(mPagesPerSide); }
    int poolPages() const { return mPoolPages; }
    /// Slots per side of the atlas: the smallest square that holds every slot.
    int atlasPagesPerSide() const { return mAtlasPagesPerSide; }
    /// Width and height of the atlas texture in texels.
    int atlasResolution() const { return mAtlasPagesPerSide * mPageSize; }

    uint32_t pageIndex(glm::ivec2 page) const { return uint32_t(page.y * mPagesPerSide + page.x); }
    glm::ivec2 pageCoord(uint32_t page) const {
        return {int(page % uint32_t(mPagesPerSide)), int(page / uint32_t(mPagesPerSide))};
    }
    /// The atlas texel where slot `slot`'s page starts (its lower-left corner).
    glm::ivec2 atlasOrigin(uint32_t slot) const {
        return glm::ivec2(int(slot % uint32_t(mAtlasPagesPerSide)),
                          int(slot / uint32_t(mAtlasPagesPerSide))) *
               mPageSize;
    }
    /// The pages that the virtual texel range [lo, hi] (texel units, either end inclusive) touches,
    /// clipped to the map; empty when the range lies wholly outside it.
    PageRect pagesOfTexels(glm::vec2 lo, glm::vec2 hi) const;

private:
    int mVirtualResolution;
    int mPageSize;
    int mPagesPerSide;
    int mPoolPages;
    int mAtlasPagesPerSide;
};

} // namespace sb
