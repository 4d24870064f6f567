// `virtual`'s page table as the shaders read it (NOTES-virtual.md, "Data structures"): one word per
// page of the virtual map, PageTable::packed in techniques/virtual/PageTable.h: bit 31 mapped, bit 30
// drawn this frame, the pool slot in bits 0-23. Slot s starts at atlas texel (s mod ATLAS_PAGES,
// s / ATLAS_PAGES) * PAGE_SIZE (PageGeometry::atlasOrigin). VIRTUAL_RESOLUTION, PAGE_SIZE, ATLAS_PAGES,
// FOOTPRINT and PCF_SIZE are defines (Virtual::addPageDefines).
const uint kPageMapped = 0x80000000u;
const uint kPageRender = 0x40000000u;
const uint kPageSlotMask = 0x00ffffffu;
const int kPagesPerSide = VIRTUAL_RESOLUTION / PAGE_SIZE;

ivec2 atlasOrigin(uint slot) {
    return ivec2(int(slot % uint(ATLAS_PAGES)), int(slot / uint(ATLAS_PAGES))) * PAGE_SIZE;
}
