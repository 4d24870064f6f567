#include "techniques/virtual/PagePool.h"

#include <algorithm>

namespace sb {

PagePool::PagePool(uint32_t slots) : mOwner(slots, kNone), mLastUsed(slots, 0) {
    for (uint32_t s = 0; s < slots; ++s) mFree.insert(mFree.end(), s);
}

uint32_t PagePool::acquire(uint32_t page, uint64_t frame) {
    if (mFree.empty()) return kNone;
    const uint32_t slot = *mFree.begin();
    mFree.erase(mFree.begin());
    mOwner[slot] = page;
    mLastUsed[slot] = frame;
    return slot;
}

void PagePool::release(uint32_t slot) {
    mOwner[slot] = kNone;
    mFree.insert(slot);
}

std::vector<uint32_t> PagePool::leastRecentlyUsed(const std::function<bool(uint32_t page)>& evictable) const {
    std::vector<uint32_t> out;
    for (uint32_t s = 0; s < size(); ++s)
        if (mOwner[s] != kNone && evictable(mOwner[s])) out.push_back(s);
    std::stable_sort(out.begin(), out.end(),
                     [&](uint32_t a, uint32_t b) { return mLastUsed[a] < mLastUsed[b]; });
    return out;
}

} // namespace sb
