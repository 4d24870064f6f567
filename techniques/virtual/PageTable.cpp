#include "techniques/virtual/PageTable.h"

namespace sb {

PageTable::PageTable(uint32_t pageCount) : mSlot(pageCount, kNoSlot), mValid(pageCount, 0) {}

void PageTable::map(uint32_t page, uint32_t slot) {
    mSlot[page] = slot;
    mValid[page] = 0;
}

void PageTable::unmap(uint32_t page) {
    mSlot[page] = kNoSlot;
    mValid[page] = 0;
}

uint32_t PageTable::packed(uint32_t page) const {
    if (!mapped(page)) return 0;
    return kMappedBit | (valid(page) ? 0u : kRenderBit) | (mSlot[page] & kSlotMask);
}

} // namespace sb
