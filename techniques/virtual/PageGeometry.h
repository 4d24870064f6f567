#pragma once
// `virtual`'s sizes (NOTES-virtual.md, "Data structures"): a square virtual shadow map of
// `virtualResolution` texels cut into square pages of `pageSize` texels (Epic's UE5 documentation,
// "Virtual Shadow Maps": a 16k^2 virtual map in 128^2 pages), its `levels` mip levels (level l has
// virtualResolution / 2^l texels a side in pages of the same pageSize: a receiver reads the level whose
// texels match its pixel, NOTES-virtual.md, "Levels"), and the physical pool that backs the pages in
// use: `poolPages` page slots laid out as a square 2D atlas texture, slot s at column s mod side and
// row s / side. Pages are numbered level by level, row-major within a level (page (x, y) of level l is
// levelOffset(l) + y * pagesPerSide(l) + x), the numbering the GPU's page table uses too (one word per
// page, PageTable::packed, in a texture pagesPerSide() words wide: shaders/virtual/page_table.glsl).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace sb {

/// An inclusive rectangle of pages (lo <= hi on both axes), or empty.
struct PageRect {
    glm::ivec2 lo{0};
    glm::ivec2 hi{-1};
    bool empty() const { return hi.x < lo.x || hi.y < lo.y; }
    uint32_t count() const { return empty() ? 0u : uint32_t((hi.x - lo.x + 1) * (hi.y - lo.y + 1)); }
    /// The pages of level `level` that hold this rectangle of level 0's pages.
    PageRect atLevel(int level) const {
        return empty() ? *this
                       : PageRect{glm::ivec2(lo.x >> level, lo.y >> level),
                                  glm::ivec2(hi.x >> level, hi.y >> level)};
    }
};

/// A page's level and its page coordinates within the level.
struct PageAddress {
    int level = 0;
    glm::ivec2 page{0};
};

class PageGeometry {
public:
    /// Throws sb::Error (ExitCode::BadInput) naming the value when `pageSize` is below 8,
    /// `virtualResolution` is not a positive multiple of it, `levels` is below 1 or more than halving
    /// the page count per side allows (2^(levels-1) must divide it), or `poolPages` is below 1 or above
    /// the page count of all levels (a larger pool could never be filled).
    PageGeometry(int virtualResolution, int pageSize, int poolPages, int levels = 1);
    /// The most levels `virtualResolution` / `pageSize` allows: down to a level of one page, or to the
    /// last level whose page count per side is whole. 0 when the sizes do not tile.
    static int maxLevels(int virtualResolution, int pageSize);

    int virtualResolution() const { return mVirtualResolution; }
    int pageSize() const { return mPageSize; }
    int levels() const { return mLevels; }
    /// Pages per side of level 0 (also the width of the GPU's page table, in words).
    int pagesPerSide() const { return mPagesPerSide; }
    int pagesPerSide(int level) const { return mPagesPerSide >> level; }
    /// Texels per side of level `level`.
    int levelResolution(int level) const { return mVirtualResolution >> level; }
    /// The number of level `level`'s first page.
    uint32_t levelOffset(int level) const { return mLevelOffset[size_t(level)]; }
    /// Pages of every level.
    uint32_t pageCount() const { return mLevelOffset.back(); }
    /// Rows of the GPU's page table: pageCount() words pagesPerSide() to a row.
    int tableRows() const {
        return int((pageCount() + uint32_t(mPagesPerSide) - 1) / uint32_t(mPagesPerSide));
    }
    int poolPages() const { return mPoolPages; }
    /// Slots per side of the atlas: the smallest square that holds every slot.
    int atlasPagesPerSide() const { return mAtlasPagesPerSide; }
    /// Width and height of the atlas texture in texels.
    int atlasResolution() const { return mAtlasPagesPerSide * mPageSize; }

    /// Page (x, y) of level 0.
    uint32_t pageIndex(glm::ivec2 page) const { return uint32_t(page.y * mPagesPerSide + page.x); }
    uint32_t pageIndex(int level, glm::ivec2 page) const {
        return levelOffset(level) + uint32_t(page.y * pagesPerSide(level) + page.x);
    }
    /// Level 0's page coordinates of page `page` (a page of level 0).
    glm::ivec2 pageCoord(uint32_t page) const { return address(page).page; }
    PageAddress address(uint32_t page) const;
    /// The atlas texel where slot `slot`'s page starts (its lower-left corner).
    glm::ivec2 atlasOrigin(uint32_t slot) const {
        return glm::ivec2(int(slot % uint32_t(mAtlasPagesPerSide)),
                          int(slot / uint32_t(mAtlasPagesPerSide))) *
               mPageSize;
    }
    /// The pages of level `level` that its texel range [lo, hi] (texel units of that level, either end
    /// inclusive) touches, clipped to the level; empty when the range lies wholly outside it.
    PageRect pagesOfTexels(glm::vec2 lo, glm::vec2 hi, int level = 0) const;

private:
    int mVirtualResolution;
    int mPageSize;
    int mPagesPerSide;
    int mLevels;
    std::vector<uint32_t> mLevelOffset; ///< per level its first page, then the total
    int mPoolPages;
    int mAtlasPagesPerSide;
};

} // namespace sb
