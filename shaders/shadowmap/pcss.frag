// `pcss` lighting pass: Percentage-Closer Soft Shadows (Fernando 2005, SIGGRAPH sketch; the NVIDIA
// whitepaper's three steps), per light (techniques/shadowmap/Pcss.h has the derivation):
//   1. blocker search over the region the light covers seen from the receiver through the map's near
//      plane, in raw depths (uDepthMap: a sampler without comparison);
//   2. penumbra width by similar triangles, w = L (d_r - d_b) / d_b, from the average blocker depth;
//   3. PCF over that width (uShadowMap: the same texture through a comparison sampler, bilinear).
// Depths are linearised before they enter a ratio (perspective maps of spot lights); an orthographic map's
// depth is linear already and its light has a fixed angular size (d_b's division drops out). Every tap
// compares with the receiver plane's depth at the tap (Isidoro 2006, shadowmap/receiver_plane.glsl).
#include "common/frame.glsl"
#include "common/lighting.glsl"
#include "common/contact_shadow.glsl"
#include "shadowmap/receiver_plane.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vColorId;
in vec4 vShadowCoord[LIGHT_COUNT];
layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oVisibility;

#ifdef VULKAN
// Set 1 (techniques/shadowmap/PcssVulkan.h): the uniforms GL sets by location, in one block whose head
// common/scene.vert reads, and the one map through two samplers. std140: each vec2 of an array takes 16
// bytes.
layout(std140, set = 1, binding = 0) uniform ShadowMapBlock {
    mat4 uShadowMatrix[LIGHT_COUNT];
    vec4 uPcssLight[LIGHT_COUNT];
    vec4 uPcssSearch[LIGHT_COUNT];
    vec2 uBlockerKernel[64];
    vec2 uFilterKernel[64];
    ivec2 uTaps;
};
layout(set = 1, binding = 1) uniform sampler2DArray uDepthMap;       // nearest, no comparison
layout(set = 1, binding = 2) uniform sampler2DArrayShadow uShadowMap; // linear, comparison
#else
layout(binding = 0) uniform sampler2DArray uDepthMap;       // nearest, no comparison: the search
layout(binding = 1) uniform sampler2DArrayShadow uShadowMap; // linear, comparison: the filter
// x: light size L; y: 1 perspective map, 0 orthographic; z, w: near and far of the linear depth.
layout(location = 12) uniform vec4 uPcssLight[LIGHT_COUNT];
// xy: world extent of the map along u and v (perspective: at linear depth 1); z: linear depth of the
// nearest caster, where the blocker search's region is measured.
layout(location = 16) uniform vec4 uPcssSearch[LIGHT_COUNT];
// Poisson disks (unit radius) of the search and the filter, and their tap counts (x: search, y: filter):
// uniforms rather than defines, so that the tap counts cost no program permutation.
layout(location = 20) uniform vec2 uBlockerKernel[64];
layout(location = 84) uniform vec2 uFilterKernel[64];
layout(location = 148) uniform ivec2 uTaps;
#endif

bool perspectiveMap(int i) { return uPcssLight[i].y > 0.5; }

// Linear depth along the light's axis of a map depth d in [0, 1].
float linearDepth(int i, float d) {
    vec4 l = uPcssLight[i];
    if (perspectiveMap(i)) return l.z * l.w / (l.w - d * (l.w - l.z));
    return d * l.w;
}

// Width, in texture units along u and v at the receiver, of the light seen from a receiver at linear
// depth zr through depth z: L (zr - z) / z in world units for a perspective map (then divided by the
// map's extent at zr), L (zr - z) for an orthographic one.
vec2 footprint(int i, float zr, float z) {
    vec4 l = uPcssLight[i];
    float world = l.x * max(zr - z, 0.0) / (perspectiveMap(i) ? z : 1.0);
    return vec2(world) / (uPcssSearch[i].xy * (perspectiveMap(i) ? zr : 1.0));
}

float pcss(int layer, vec4 coord, vec2 slope) {
    // Behind a spot light (w <= 0) nothing is lit by it anyway; treat as lit so the term decides.
    if (coord.w <= 0.0) return 1.0;
    vec3 p = coord.xyz / coord.w;
    // Beyond the map's far plane nothing was rendered behind the receiver.
    if (p.z > 1.0) return 1.0;
    vec2 texel = 1.0 / vec2(textureSize(uShadowMap, 0).xy);
    float z = p.z - receiverQuantisation(slope, texel);
    float zr = linearDepth(layer, p.z);

    // Step 1: blocker search. Casters between the receiver and the light lie in the light's footprint
    // seen through the nearest caster's depth; at most half the map either way. A directional map is
    // fitted to the casters, but their penumbrae reach past it: a receiver outside the map searches too
    // (the samplers' border is depth 1, no caster), unless its search region misses the map entirely.
    vec2 searchRadius = clamp(0.5 * footprint(layer, zr, uPcssSearch[layer].z), texel, vec2(0.5));
    if (any(lessThan(p.xy, -searchRadius)) || any(greaterThan(p.xy, 1.0 + searchRadius))) return 1.0;
    float blockerSum = 0.0;
    int blockers = 0;
    for (int k = 0; k < uTaps.x; ++k) {
        vec2 o = uBlockerKernel[k] * searchRadius;
        float d = textureLod(uDepthMap, vec3(p.xy + o, float(layer)), 0.0).r;
        if (d < z + dot(slope, o)) {
            blockerSum += linearDepth(layer, d);
            ++blockers;
        }
    }
    if (blockers == 0) return 1.0; // nothing in front of the receiver: fully lit

    // Step 2: penumbra width from the average blocker depth (similar triangles); at least one texel,
    // the hard shadow's bilinear footprint, so a caster touching the receiver gives a hard contact.
    float zb = blockerSum / float(blockers);
    vec2 filterRadius = clamp(0.5 * footprint(layer, zr, zb), texel, searchRadius);

    // Step 3: PCF over the penumbra.
    float sum = 0.0;
    for (int k = 0; k < uTaps.y; ++k) {
        vec2 o = uFilterKernel[k] * filterRadius;
        sum += texture(uShadowMap, vec4(p.xy + o, float(layer), z + dot(slope, o)));
    }
    return sum / float(uTaps.y);
}

void main() {
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing) n = -n;
    vec3 light = ambientLight();
    vec4 vis = vec4(1.0);
    for (int i = 0; i < LIGHT_COUNT; ++i) {
        vec4 coord = vShadowCoord[i];
        vec2 slope = receiverSlope(coord.xyz / coord.w); // before any branch: derivatives
        vis[i] = shadowApplies(i, vColorId) ? contactLimited(i, pcss(i, coord, slope), vWorldPos, n)
                                            : 1.0;
        light += vis[i] * lightTerm(i, vWorldPos, n);
    }
    oColor = vec4(vColorId.rgb * light, 1.0);
    oVisibility = vis;
}
