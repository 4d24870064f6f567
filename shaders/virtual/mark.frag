// `virtual`'s page marking (PageMarking in techniques/virtual/PageMarking.h states the same rule on the
// CPU): the visible receiver fragment at world position p projects into the light's map at texel t, and
// its lookup reads texels within FOOTPRINT of t, so every page that square touches is stored as needed.
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

layout(binding = 0, r32ui) uniform writeonly uimage2D uRequests;
layout(location = 10) uniform mat4 uLightMatrix; // bias * viewProj: world -> [0, 1] map coordinates
layout(location = 14) uniform int uMark;

void main() {
    if (uMark == 0) return;
    vec4 c = uLightMatrix * vec4(vWorldPos, 1.0);
    if (c.w <= 0.0) return;
    vec2 t = c.xy / c.w * float(VIRTUAL_RESOLUTION);
    vec2 lo = t - FOOTPRINT;
    vec2 hi = t + FOOTPRINT;
    // Wholly outside the map: the lookup says lit, nothing to read.
    if (any(lessThan(hi, vec2(0.0))) || any(greaterThanEqual(lo, vec2(float(VIRTUAL_RESOLUTION))))) return;
    ivec2 a = clamp(ivec2(floor(max(lo, vec2(0.0)) / float(PAGE_SIZE))), ivec2(0), ivec2(kPagesPerSide - 1));
    ivec2 b = clamp(ivec2(floor(min(hi, vec2(float(VIRTUAL_RESOLUTION - 1))) / float(PAGE_SIZE))), ivec2(0),
                    ivec2(kPagesPerSide - 1));
    for (int y = a.y; y <= b.y; ++y)
        for (int x = a.x; x <= b.x; ++x) imageStore(uRequests, ivec2(x, y), uvec4(1u));
}
