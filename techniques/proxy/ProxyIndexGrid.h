#pragma once
// The IndexMap of the ShadowProxies technique (OpenGL Insights, section 1.3), built on the CPU each
// frame: the proxies in view are numbered, the viewport is split into a grid of cells, and each
// proxy's index goes into every cell its projected bounds overlap, so a fragment tests only the
// proxies of its cell (Listing 1.2).
//
// Past the chapter's limits: indices are 32-bit (the chapter's GLubyte texels cap them at 255), the
// cell capacity is a parameter, and a proxy that does not fit into a full cell is counted (overflow),
// never dropped silently. The bounds are those of the influence volume: the proxy's box grown by
// ProxyOffset in world space, since a fragment that far from the surface is still darkened.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/ShadowProxy.h"

namespace sb {

class ProxyIndexGrid {
public:
    /// Rebuilds the grid: `cellsX` x `cellsY` cells over the viewport of `viewProj`, `capacity` indices
    /// per cell. Step 2 of the pipeline: a proxy whose grown box lies entirely outside one frustum plane
    /// is clipped away (not numbered); one reaching behind the eye (a corner with w <= 0) covers every
    /// cell (its projection is unbounded). Reuses its storage: no allocation once grown.
    void build(const std::vector<ShadowProxy>& proxies, const glm::mat4& viewProj, float proxyOffset,
               int cellsX, int cellsY, int capacity);

    /// Indices into the `proxies` passed to build(), of those in view, in numbering order: the index a
    /// cell holds is a position in this list (the chapter's "index of the proxy in the list of proxies
    /// that are in view").
    const std::vector<uint32_t>& visible() const { return mVisible; }
    int cellsX() const { return mCellsX; }
    int cellsY() const { return mCellsY; }
    int capacity() const { return mCapacity; }
    /// Indices stored in cell (x, y), y = 0 at the bottom of the viewport.
    uint32_t count(int x, int y) const { return mCounts[size_t(y) * size_t(mCellsX) + size_t(x)]; }
    const uint32_t* cell(int x, int y) const {
        return &mIndices[(size_t(y) * size_t(mCellsX) + size_t(x)) * size_t(mCapacity)];
    }
    /// (Proxy, cell) pairs that did not fit because the cell was full, since the last build().
    uint64_t overflow() const { return mOverflow; }
    /// Indices stored over all cells, and the most in one cell, since the last build().
    uint64_t entries() const { return mEntries; }
    uint32_t maxCount() const { return mMaxCount; }
    /// The GPU layout: per cell `capacity` entries, each a visible index + 1, 0 ending the list (the
    /// chapter's convention: 0 means no more proxies).
    const std::vector<uint32_t>& texels() const { return mIndices; }

private:
    std::vector<uint32_t> mVisible, mIndices, mCounts;
    int mCellsX = 0, mCellsY = 0, mCapacity = 0;
    uint64_t mOverflow = 0, mEntries = 0;
    uint32_t mMaxCount = 0;
};

} // namespace sb
