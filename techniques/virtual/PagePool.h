#pragma once
// `virtual`'s physical page pool (NOTES-virtual.md, "Data structures"): the slots of the atlas texture
// (PageGeometry), each free or owned by one virtual page, with the frame it was last needed in. Free
// slots are handed out lowest first, so that a run's allocation, and with it every image and counter,
// is the same from run to run. When none is free, VirtualPageCache evicts the least recently needed
// page (leastRecentlyUsed): the cache keeps pages no frame needs any more for as long as the pool has
// room, as UE5's page cache and the GPU Zen 3 chapter "Virtual Shadow Maps" (Sakmary, Ryan, Hall,
// Lustri) keep theirs.
#include <cstdint>
#include <functional>
#include <set>
#include <vector>

namespace sb {

class PagePool {
public:
    static constexpr uint32_t kNone = 0xffffffffu;

    explicit PagePool(uint32_t slots);

    uint32_t size() const { return uint32_t(mOwner.size()); }
    uint32_t freeCount() const { return uint32_t(mFree.size()); }
    /// The virtual page that owns `slot`, or kNone.
    uint32_t owner(uint32_t slot) const { return mOwner[slot]; }
    uint64_t lastUsed(uint32_t slot) const { return mLastUsed[slot]; }
    /// The lowest free slot, now owned by `page` and used in `frame`; kNone when no slot is free.
    uint32_t acquire(uint32_t page, uint64_t frame);
    /// `slot`'s page was needed in `frame`.
    void touch(uint32_t slot, uint64_t frame) { mLastUsed[slot] = frame; }
    /// `slot` is free again.
    void release(uint32_t slot);
    /// The owned slots whose owner `evictable` accepts, least recently used first (ties: lower slot
    /// first): the order in which the cache takes slots back when none is free.
    std::vector<uint32_t> leastRecentlyUsed(const std::function<bool(uint32_t page)>& evictable) const;

private:
    std::vector<uint32_t> mOwner;
    std::vector<uint64_t> mLastUsed;
    std::set<uint32_t> mFree;
};

} // namespace sb
