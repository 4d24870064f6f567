// `virtual`'s page marking (PageMarking in techniques/virtual/PageMarking.h states the same rule on the
// CPU): the visible receiver fragment at world position p projects into the light's map at level 0's
// texel t; it reads the level pageLevel(pageLod(t)) (shaders/virtual/page_table.glsl), there texels
// within the footprint of t / 2^level, so every page of that level the square touches is stored as needed.
// The level is also marked for a lod kLodMargin either side, so that the lighting pass, which picks the
// level again, finds its pages even if its derivatives differ in the last bits.
// Drawn twice with the same program (VirtualGL::markPages): uMark 0 lays the receivers' depth, uMark 1
// draws them again with an EQUAL depth test, and early fragment tests keep the hidden fragments from
// running, so only what the camera sees marks.
#include "common/frame.glsl"
#include "common/lighting.glsl"
#include "virtual/page_table.glsl"

layout(early_fragment_tests) in;

in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vColorId;

#ifdef VULKAN
// Set 1 (techniques/virtual/VirtualVulkan.h): virtual/page_table.glsl's block; uMark in the push
// constants.
#include "common/push.glsl"
layout(set = 1, binding = 1, r32ui) uniform writeonly uimage2D uRequests;
#define uMark uPush.ints.y
#else
layout(binding = 0, r32ui) uniform writeonly uimage2D uRequests;
layout(location = 10) uniform mat4 uLightMatrix; // bias * viewProj: world -> [0, 1] map coordinates
layout(location = 14) uniform int uMark;
#endif

const float kLodMargin = 1.0 / 16.0;

void markLevel(vec2 t, int level) {
    float resolution = float(virtualResolution() >> level);
    vec2 tl = t / float(1 << level);
    vec2 lo = tl - uPageLod.x;
    vec2 hi = tl + uPageLod.x;
    // Wholly outside the map: the lookup says lit, nothing to read.
    if (any(lessThan(hi, vec2(0.0))) || any(greaterThanEqual(lo, vec2(resolution)))) return;
    int last = (pagesPerSide() >> level) - 1;
    float page = float(pageSize());
    ivec2 a = clamp(ivec2(floor(max(lo, vec2(0.0)) / page)), ivec2(0), ivec2(last));
    ivec2 b = clamp(ivec2(floor(min(hi, vec2(resolution - 1.0)) / page)), ivec2(0), ivec2(last));
    for (int y = a.y; y <= b.y; ++y)
        for (int x = a.x; x <= b.x; ++x) imageStore(uRequests, tableTexel(level, ivec2(x, y)), uvec4(1u));
}

void main() {
    vec4 c = uLightMatrix * vec4(vWorldPos, 1.0);
    vec2 t = c.xy / c.w * float(virtualResolution());
    float lod = pageLod(t); // before any branch
    if (uMark == 0 || c.w <= 0.0) return;
    int lo = pageLevel(lod - kLodMargin);
    int hi = pageLevel(lod + kLodMargin);
    markLevel(t, lo);
    if (hi != lo) markLevel(t, hi);
}
