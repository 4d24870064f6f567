// `cascaded` lighting pass (Engel 2006, Cascaded Shadow Maps, ShaderX5; Dimitrov 2007, Cascaded
// Shadow Maps, NVIDIA): each fragment picks its cascade by view depth, the first whose far split lies
// beyond it, and looks its world position up in that cascade's layer of the depth array. With BLEND,
// in the last `blend` fraction of a cascade it blends linearly into the next one, whose map covers
// that band too, so the jump in texel size at a split is no seam. PCF_SIZE x PCF_SIZE hardware-compare taps
// one texel apart (bilinear), as `shadowmap`. A spot light has one layer (a perspective map).
#include "common/frame.glsl"
#include "common/lighting.glsl"
#include "common/contact_shadow.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vColorId;
layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oVisibility;

#ifdef VULKAN
// Set 1 (techniques/shadowmap/CascadedVulkan.h): the uniforms GL sets by location, in one block, and the
// map. std140: each int of an array takes 16 bytes.
layout(std140, set = 1, binding = 0) uniform CascadedBlock {
    vec4 uSplitFar;
    vec4 uBandStart;
    vec4 uBandScale;
    uint uEmptySlots;
    mat4 uSlotMatrix[SLOT_COUNT];
    int uSlotLayer[SLOT_COUNT];
};
layout(set = 1, binding = 1) uniform sampler2DArrayShadow uShadowMap;
#else
layout(binding = 0) uniform sampler2DArrayShadow uShadowMap;
layout(location = 10) uniform vec4 uSplitFar;               // view depth where cascade c ends
layout(location = 11) uniform vec4 uBandStart;              // view depth where cascade c's blend band begins
layout(location = 12) uniform vec4 uBandScale;              // 1 / the band's width; 0 for the last cascade
layout(location = 15) uniform uint uEmptySlots;             // bit per slot: no caster in its map, lit
layout(location = 16) uniform mat4 uSlotMatrix[SLOT_COUNT]; // bias * ortho * lightView per slot
layout(location = 32) uniform int uSlotLayer[SLOT_COUNT];   // the depth array's layer of each slot
#endif

// Per light, compile-time constants (the light loop unrolls, so every branch on them folds: on a
// rasteriser that runs both sides of a branch, as llvmpipe does, a spot light pays no cascade code
// and one cascade no blend): its first slot and its slots (CASCADE_COUNT, or 1 for a spot light).
const int kFirstSlot[LIGHT_COUNT] = int[](FIRST_SLOTS);
const int kSlots[LIGHT_COUNT] = int[](LIGHT_SLOTS);

// A slot is one cascade of a light (or a spot light's one map); identical cascades share a layer.
float slotVisibility(int slot, vec3 world) {
    if ((uEmptySlots & (1u << uint(slot))) != 0u) return 1.0;
    vec4 coord = uSlotMatrix[slot] * vec4(world, 1.0);
    // Behind a spot light (w <= 0) nothing is lit by it anyway; treat as lit so the term decides.
    if (coord.w <= 0.0) return 1.0;
    vec3 p = coord.xyz / coord.w;
    // Outside the map: no occluder was rendered there.
    if (any(lessThan(p.xy, vec2(0.0))) || any(greaterThan(p.xy, vec2(1.0))) || p.z > 1.0) return 1.0;
    vec2 texel = 1.0 / vec2(textureSize(uShadowMap, 0).xy);
    const float half_ = 0.5 * float(PCF_SIZE - 1);
    float sum = 0.0;
    for (int y = 0; y < PCF_SIZE; ++y)
        for (int x = 0; x < PCF_SIZE; ++x)
            sum +=
                texture(uShadowMap, vec4(p.xy + (vec2(x, y) - half_) * texel, float(uSlotLayer[slot]), p.z));
    return sum / float(PCF_SIZE * PCF_SIZE);
}

float visibility(int light, vec3 world, float viewDepth) {
    int first = kFirstSlot[light];
    if (kSlots[light] == 0) return 1.0; // a scene without lights
    if (kSlots[light] == 1) return slotVisibility(first, world);
    // The first cascade whose far split lies beyond the fragment (the splits increase).
    int c = 0;
    for (int k = 0; k < CASCADE_COUNT - 1; ++k) c += viewDepth > uSplitFar[k] ? 1 : 0;
    float v = slotVisibility(first + c, world);
#ifdef BLEND
    // Over the band at the end of cascade c, linearly into cascade c + 1, which covers the band too.
    float t = clamp((viewDepth - uBandStart[c]) * uBandScale[c], 0.0, 1.0);
    if (t > 0.0) v = mix(v, slotVisibility(first + min(c + 1, CASCADE_COUNT - 1), world), t);
#endif
    return v;
}

void main() {
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing) n = -n;
    float viewDepth = -(uView * vec4(vWorldPos, 1.0)).z;
    vec3 light = ambientLight();
    vec4 vis = vec4(1.0);
    for (int i = 0; i < LIGHT_COUNT; ++i) {
        vis[i] = shadowApplies(i, vColorId)
                     ? contactLimited(i, visibility(i, vWorldPos, viewDepth), vWorldPos, n)
                     : 1.0;
        light += vis[i] * lightTerm(i, vWorldPos, n);
    }
    oColor = vec4(vColorId.rgb * light, 1.0);
    oVisibility = vis;
}
