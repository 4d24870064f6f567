#include "techniques/virtual/VirtualPageCache.h"

namespace sb {

VirtualPageCache::VirtualPageCache(const PageGeometry& geometry)
    : mGeometry(geometry), mTable(geometry.pageCount()), mPool(uint32_t(geometry.poolPages())) {}

void VirtualPageCache::drop(uint32_t page) {
    if (!mTable.mapped(page)) return;
    if (mTable.valid(page)) ++mCounts.invalidated;
    mPool.release(mTable.slot(page));
    mTable.unmap(page);
}

void VirtualPageCache::beginFrame(const glm::mat4& lightViewProj, bool cache) {
    ++mFrame;
    mCounts = {};
    mRender.clear();
    const bool moved = mStarted && lightViewProj != mLightViewProj;
    mLightViewProj = lightViewProj;
    mStarted = true;
    if (cache && !moved) return;
    for (uint32_t page = 0; page < mTable.size(); ++page) drop(page);
    if (!cache) mCounts.invalidated = 0; // no cache: nothing was kept to go stale
}

void VirtualPageCache::invalidate(const std::vector<PageRect>& rects) {
    for (const PageRect& base : rects)
        for (int level = 0; level < mGeometry.levels(); ++level) {
            const PageRect r = base.atLevel(level);
            for (int y = r.lo.y; y <= r.hi.y; ++y)
                for (int x = r.lo.x; x <= r.hi.x; ++x) drop(mGeometry.pageIndex(level, {x, y}));
        }
}

const std::vector<uint32_t>& VirtualPageCache::allocate(const std::vector<uint8_t>& needed) {
    std::vector<uint32_t> victims; // the eviction order, taken once, the first time no slot is free
    size_t nextVictim = 0;
    bool victimsListed = false;
    for (uint32_t page = 0; page < mTable.size(); ++page) {
        if (!needed[page]) continue;
        ++mCounts.needed;
        if (mTable.mapped(page)) {
            mPool.touch(mTable.slot(page), mFrame);
            if (mTable.valid(page))
                ++mCounts.reused;
            else
                mRender.push_back(page);
            continue;
        }
        uint32_t slot = mPool.acquire(page, mFrame);
        if (slot == PagePool::kNone) {
            if (!victimsListed) {
                victims = mPool.leastRecentlyUsed([&](uint32_t owner) { return !needed[owner]; });
                victimsListed = true;
            }
            if (nextVictim == victims.size()) {
                ++mCounts.dropped;
                continue;
            }
            const uint32_t victim = mPool.owner(victims[nextVictim++]);
            mPool.release(mTable.slot(victim));
            mTable.unmap(victim);
            ++mCounts.evicted;
            slot = mPool.acquire(page, mFrame);
        }
        mTable.map(page, slot);
        ++mCounts.allocated;
        mRender.push_back(page);
    }
    mCounts.rendered = uint32_t(mRender.size());
    mCounts.resident = mPool.size() - mPool.freeCount();
    return mRender;
}

void VirtualPageCache::rendered() {
    for (uint32_t page : mRender) mTable.setValid(page);
}

void VirtualPageCache::packTable(std::vector<uint32_t>& out) const {
    out.resize(mTable.size());
    for (uint32_t page = 0; page < mTable.size(); ++page) out[page] = mTable.packed(page);
}

} // namespace sb
