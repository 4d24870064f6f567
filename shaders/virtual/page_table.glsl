// `virtual`'s page table as the shaders read it (NOTES-virtual.md, "Data structures"): one word per
// page of the virtual map, PageTable::packed in techniques/virtual/PageTable.h: bit 31 mapped, bit 30
// drawn this frame, the pool slot in bits 0-23. The words of every level in PageGeometry's numbering
// (level by level, row-major within one), pagesPerSide() words to a row of the table texture. Slot s
// starts at atlas texel (s mod atlas side, s / atlas side) * page size (PageGeometry::atlasOrigin).
// The sizes are uniforms, not defines (Virtual::pageUniforms), so that a size costs no program:
// uPageGeometry = (virtual resolution, page size, atlas pages a side, levels), uPageLod = (the marking
// footprint in texels, lod_bias, the PCF kernel's width, 0).
#ifdef VULKAN
// Set 1 (techniques/virtual/VirtualVulkan.h): what GL sets by location, in one block.
layout(std140, set = 1, binding = 0) uniform VirtualBlock {
    mat4 uLightViewProj; // common/depth.vert's, for the page pass
    mat4 uLightMatrix;   // bias * viewProj: world -> [0, 1] map coordinates
    ivec4 uPageGeometry;
    vec4 uPageLod;
};
#else
layout(location = 20) uniform ivec4 uPageGeometry;
layout(location = 21) uniform vec4 uPageLod;
#endif
const uint kPageMapped = 0x80000000u;
const uint kPageRender = 0x40000000u;
const uint kPageSlotMask = 0x00ffffffu;

int virtualResolution() {
    return uPageGeometry.x;
}
int pageSize() {
    return uPageGeometry.y;
}
/// Pages a side of level 0, and words a row of the table.
int pagesPerSide() {
    return uPageGeometry.x / uPageGeometry.y;
}

ivec2 atlasOrigin(uint slot) {
    uint side = uint(uPageGeometry.z);
    return ivec2(int(slot % side), int(slot / side)) * pageSize();
}

/// The table texel of page `page` of level `level` (PageGeometry::pageIndex: the levels before it hold
/// sum_k<level (N / 2^k)^2 = (4 N^2 - 4 (N / 2^level)^2) / 3 pages, N = pagesPerSide()).
ivec2 tableTexel(int level, ivec2 page) {
    int n = pagesPerSide();
    int side = n >> level;
    int index = (4 * n * n - 4 * side * side) / 3 + page.y * side + page.x;
    return ivec2(index % n, index / n);
}

/// log2 of level 0's texels per screen pixel at virtual texel `t` (level 0's units), plus lod_bias: the
/// level whose texels are a pixel wide is its floor. Derivatives: call it in uniform control flow. The
/// marking pass and the lighting pass call this one function on the same inputs.
float pageLod(vec2 t) {
    float texelsPerPixel = max(length(dFdx(t)), length(dFdy(t)));
    return log2(max(texelsPerPixel, 1e-20)) + uPageLod.y;
}

/// Taps a side of the lighting pass's kernel (pcf).
int pcfSize() {
    return int(uPageLod.z);
}

int pageLevel(float lod) {
    return clamp(int(floor(lod)), 0, uPageGeometry.w - 1);
}
