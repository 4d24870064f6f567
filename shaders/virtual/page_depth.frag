// `virtual`'s page depth, the atomic path (Blender EEVEE-Next's eevee_surf_shadow_frag.glsl describes
// it): the casters are rasterized in the coordinates of one whole level of the virtual map into a
// framebuffer with no attachments, under a scissor around the pages being drawn; each fragment finds
// its page's word and, where the page is drawn this frame, keeps the nearest depth in its slot of the
// atlas with an atomic min (a positive float's bits order as the float). Rasterizing in virtual
// coordinates, whatever the slot, gives a page the same bits wherever it lives: cached and fresh pages
// are identical. glPolygonOffset does not reach an image store, so its formula is applied here: slope *
// max|dz| + constant * 2^-24 (the step of `shadowmap`'s 24-bit maps, so the bias knobs mean the same).
#include "virtual/page_table.glsl"

#ifdef VULKAN
// Set 1 (techniques/virtual/VirtualVulkan.h); the bias and the level in the push constants.
#include "common/push.glsl"
layout(set = 1, binding = 2, r32ui) uniform coherent uimage2D uAtlas;
layout(set = 1, binding = 4) uniform usampler2D uPageTable;
#define uBias uPush.vec.xy
#define uLevel uPush.ints.y
#else
layout(binding = 0, r32ui) uniform coherent uimage2D uAtlas;
layout(binding = 1) uniform usampler2D uPageTable;
layout(location = 16) uniform vec2 uBias; // constant, slope
layout(location = 17) uniform int uLevel; // the level drawn: the viewport is its whole map
#endif

void main() {
    float z = gl_FragCoord.z;
    // Derivatives before any branch (undefined in non-uniform control flow).
    float slope = max(abs(dFdx(z)), abs(dFdy(z)));
    ivec2 texel = ivec2(gl_FragCoord.xy);
    uint word = texelFetch(uPageTable, tableTexel(uLevel, texel / pageSize()), 0).r;
    if ((word & kPageRender) == 0u) return;
    z = clamp(z + uBias.y * slope + uBias.x * exp2(-24.0), 0.0, 1.0);
#ifdef VIRTUAL_SPARSE
    // path=sparse: uAtlas is this level of the sparse-resident map, the page bound to its slot's memory.
    imageAtomicMin(uAtlas, texel, floatBitsToUint(z));
#else
    imageAtomicMin(uAtlas, atlasOrigin(word & kPageSlotMask) + texel % pageSize(), floatBitsToUint(z));
#endif
}
