// `virtual`'s lighting pass: the mapped light's visibility through the virtual map at the level
// pageLevel(pageLod(t)) picks (shaders/virtual/page_table.glsl, as the marking pass did), pcf x pcf
// nearest taps one texel of that level apart, each through its own page's word, so a kernel
// across a page seam reads both pages (the marking footprint made sure both are there). A tap outside the map or on a page
// without a slot reads lit. The compare is `shadowmap`'s LEQUAL: lit where the receiver's depth is at
// most the stored one.
#include "common/frame.glsl"
#include "common/lighting.glsl"
#include "common/contact_shadow.glsl"
#include "virtual/page_table.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vColorId;
layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oVisibility;

#ifdef VULKAN
// Set 1 (techniques/virtual/VirtualVulkan.h): virtual/page_table.glsl's block, the atlas and the table.
layout(set = 1, binding = 3) uniform usampler2D uAtlas;
layout(set = 1, binding = 4) uniform usampler2D uPageTable;
#else
layout(binding = 0) uniform usampler2D uAtlas;
layout(binding = 1) uniform usampler2D uPageTable;
layout(location = 10) uniform mat4 uLightMatrix; // bias * viewProj
#endif

float tap(vec2 t, float z, int level) {
    if (any(lessThan(t, vec2(0.0))) || any(greaterThanEqual(t, vec2(float(virtualResolution() >> level)))))
        return 1.0;
    ivec2 texel = ivec2(floor(t));
    uint word = texelFetch(uPageTable, tableTexel(level, texel / pageSize()), 0).r;
    if ((word & kPageMapped) == 0u) return 1.0;
#ifdef VIRTUAL_SPARSE
    uint stored = texelFetch(uAtlas, texel, level).r; // path=sparse: the map itself, its levels as mips
#else
    uint stored = texelFetch(uAtlas, atlasOrigin(word & kPageSlotMask) + texel % pageSize(), 0).r;
#endif
    return z <= uintBitsToFloat(stored) ? 1.0 : 0.0;
}

float visibility(vec4 c, vec3 p, vec2 t, int level) {
    if (c.w <= 0.0 || p.z > 1.0) return 1.0; // behind a spot light, or beyond the map's far plane
    vec2 tl = t / float(1 << level);
    int n = pcfSize();
    float half_ = 0.5 * float(n - 1);
    float sum = 0.0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) sum += tap(tl + vec2(x, y) - half_, p.z, level);
    return sum / float(n * n);
}

void main() {
    // The map position and its level first: derivatives in uniform control flow (mark.frag's order).
    vec4 c = uLightMatrix * vec4(vWorldPos, 1.0);
    vec2 t = c.xy / c.w * float(virtualResolution());
    int level = pageLevel(pageLod(t));
    vec3 p = c.xyz / c.w;
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing) n = -n;
    vec3 light = ambientLight();
    vec4 vis = vec4(1.0);
    for (int i = 0; i < LIGHT_COUNT; ++i) {
        vis[i] = i == MAPPED_LIGHT && shadowApplies(i, vColorId)
                     ? contactLimited(i, visibility(c, p, t, level), vWorldPos, n)
                     : 1.0;
        light += vis[i] * lightTerm(i, vWorldPos, n);
    }
    oColor = vec4(vColorId.rgb * light, 1.0);
    oVisibility = vis;
}
