#pragma once
// `virtual`'s page table (NOTES-virtual.md, "Data structures"): per virtual page of the map
// (PageGeometry's numbering) the pool slot that backs it, if any, and whether that slot's content is
// valid: rendered under the light transform of this frame with every caster where it is now. A mapped
// page that is not valid is one the frame renders (VirtualPageCache::allocate maps it, the depth pass
// draws it, rendered() makes it valid). The GPU reads the same table as one 32-bit word per page
// (packed): the lighting pass to find a page's slot, the depth pass to write only the pages it renders.
#include <cstdint>
#include <vector>

namespace sb {

class PageTable {
public:
    static constexpr uint32_t kNoSlot = 0xffffffffu;
    /// packed(): bit 31 set when the page is mapped, bit 30 when the frame renders it (mapped and not
    /// yet valid), the slot in the low 24 bits (0 when unmapped). The shaders read the same layout
    /// (the constants are defined once more there, in GLSL, beside a comment naming this header).
    static constexpr uint32_t kMappedBit = 1u << 31;
    static constexpr uint32_t kRenderBit = 1u << 30;
    static constexpr uint32_t kSlotMask = (1u << 24) - 1;

    explicit PageTable(uint32_t pageCount);

    uint32_t size() const { return uint32_t(mSlot.size()); }
    bool mapped(uint32_t page) const { return mSlot[page] != kNoSlot; }
    uint32_t slot(uint32_t page) const { return mSlot[page]; }
    bool valid(uint32_t page) const { return mValid[page] != 0; }
    /// Backs `page` with `slot`; its content is not valid until setValid.
    void map(uint32_t page, uint32_t slot);
    /// Frees `page`'s slot from it (the caller returns the slot to the pool).
    void unmap(uint32_t page);
    void setValid(uint32_t page) { mValid[page] = 1; }
    /// The word the GPU reads for `page` (see kMappedBit).
    uint32_t packed(uint32_t page) const;

private:
    std::vector<uint32_t> mSlot; ///< per page: its slot, or kNoSlot
    std::vector<uint8_t> mValid; ///< per page: 1 when its slot's content is current
};

} // namespace sb
