#pragma once
// `virtual`'s page allocation and cache, the API-neutral core both forms run on the CPU each frame
// (NOTES-virtual.md, "Passes" step 3 and "Caching"): from the pages the frame needs (the GPU's marks,
// read back) and what moved, it decides which pages keep their cached depth, which get a slot of the
// pool and which the depth pass draws, and counts it all (PageCounts).
//
// A frame: beginFrame (the light's transform; a change, or the cache off, drops every page), invalidate
// (the pages moved casters cover, CasterFootprints), allocate (the needed pages: valid ones reused,
// mapped ones not valid drawn again, unmapped ones given a slot, the lowest free first, else the least
// recently needed page no one needs this frame is evicted; with neither, the page is dropped), the depth
// pass draws renderList(), then rendered() makes them valid.
//
// What the cache keys a page's content by: the light's transform (bit for bit: any change and no page
// is valid) and the casters over the page (a moved caster's old and new pages are invalidated). With
// both unchanged, a page's depth is what a new render would write, so a cached frame's image equals the
// same frame drawn with the cache off pixel for pixel (NOTES-virtual.md, "Tests").
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "techniques/virtual/PageCounts.h"
#include "techniques/virtual/PageGeometry.h"
#include "techniques/virtual/PagePool.h"
#include "techniques/virtual/PageTable.h"

namespace sb {

class VirtualPageCache {
public:
    explicit VirtualPageCache(const PageGeometry& geometry);

    const PageGeometry& geometry() const { return mGeometry; }
    /// Starts a frame under the light's transform `lightViewProj`. With `cache` false every page is
    /// dropped first (none counted as invalidated: there is no cache); with it true only a transform that
    /// differs from the last frame's drops them, counted as invalidated where they were valid.
    void beginFrame(const glm::mat4& lightViewProj, bool cache);
    /// The pages in `rects` (level 0's pages) lose their content on every level (the pages of level l
    /// that hold them): unmapped, slots freed, counted where they were valid.
    void invalidate(const std::vector<PageRect>& rects);
    /// Maps the frame's `needed` pages (a byte per page) and returns the ones to draw, in page order.
    const std::vector<uint32_t>& allocate(const std::vector<uint8_t>& needed);
    /// The pages allocate() returned were drawn: their content is valid.
    void rendered();

    const std::vector<uint32_t>& renderList() const { return mRender; }
    const PageTable& table() const { return mTable; }
    const PagePool& pool() const { return mPool; }
    const PageCounts& counts() const { return mCounts; }
    /// The page table as the GPU reads it: one PageTable::packed word per page.
    void packTable(std::vector<uint32_t>& out) const;

private:
    void drop(uint32_t page);

    PageGeometry mGeometry;
    PageTable mTable;
    PagePool mPool;
    glm::mat4 mLightViewProj{0.0f}; ///< the last frame's; all zeros before the first
    bool mStarted = false;
    uint64_t mFrame = 0;
    std::vector<uint32_t> mRender;
    PageCounts mCounts;
};

} // namespace sb
