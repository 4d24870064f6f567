// `shadowmap` lighting pass: compare each fragment's light-space depth with the shadow map
// (Williams 1978; the thesis section 2.4). HW_COMPARE uses a depth-compare sampler with bilinear
// filtering of the comparison results (the "hardware PCF" of every GPU since the GeForce 3); without
// it, nearest depth fetches are compared in the shader.
// Kernels (techniques/shadowmap/ShadowMapGL.h): by default PCF_SIZE x PCF_SIZE taps, one texel
// apart. KERNEL_POISSON: uKernelTaps taps of a fixed Poisson disk (Fernando 2005, Percentage-Closer Soft
// Shadows, section 3), uKernel in texels. KERNEL_ROTATED_GRID: a uKernelTaps = n x n grid rotated per pixel
// by 2 pi times interleaved gradient noise of the pixel (Jimenez 2014, Next Generation Post Processing in
// Call of Duty: Advanced Warfare, SIGGRAPH course, "interleaved gradient noise"): a function of
// gl_FragCoord only, so the image is the same in every submission mode and every run.
// Biases: NORMAL_OFFSET moves the lookup position along the surface normal by uNormalOffset world-space
// texels of the map, scaled by (1 - n.l) (Holbert 2011, Saying Goodbye to Shadow Acne, GDC 2011; Holbert
// 2010, Normal Offset Shadows); RECEIVER_PLANE compares each tap with the receiver plane's depth there
// (Isidoro 2006, shadowmap/receiver_plane.glsl). SB_CONTACT_SHADOWS: common/contact_shadow.glsl's march
// darkens what the map's bias leaves lit under a caster's foot.
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
// Set 1 (techniques/shadowmap/ShadowMapVulkan.h): the uniforms GL sets by location, in one block whose
// head common/scene.vert reads, and the map. std140: each float and vec2 of an array takes 16 bytes.
layout(std140, set = 1, binding = 0) uniform ShadowMapBlock {
    mat4 uShadowMatrix[LIGHT_COUNT];
    float uTexelWorld[LIGHT_COUNT];
    float uNormalOffset;
    int uKernelTaps;
    float uTargetHeight; // pixels: gl_FragCoord's y from the bottom, as on GL
    vec2 uKernel[64];
};
#define SB_MAP_BINDING set = 1, binding = 1
#else
#define SB_MAP_BINDING binding = 0
#endif
#ifdef HW_COMPARE
layout(SB_MAP_BINDING) uniform sampler2DArrayShadow uShadowMap;
#else
layout(SB_MAP_BINDING) uniform sampler2DArray uShadowMap;
#endif

#if defined(NORMAL_OFFSET) && !defined(VULKAN)
// The same matrices common/scene.vert projects with (one uniform across both stages).
layout(location = 8) uniform mat4 uShadowMatrix[LIGHT_COUNT];
// World size of one map texel at light-space w = 1 (orthographic: everywhere; perspective: times w).
layout(location = 12) uniform float uTexelWorld[LIGHT_COUNT];
layout(location = 16) uniform float uNormalOffset; // in texels
#endif
#if (defined(KERNEL_POISSON) || defined(KERNEL_ROTATED_GRID)) && !defined(VULKAN)
// The taps are uniforms, not defines, so that `taps` costs no program permutation.
layout(location = 17) uniform int uKernelTaps;
layout(location = 20) uniform vec2 uKernel[64]; // tap offsets in texels (radius applied)
#endif

float shadowTap(int layer, vec2 uv, float depth) {
#ifdef HW_COMPARE
    return texture(uShadowMap, vec4(uv, float(layer), depth));
#else
    return depth <= texture(uShadowMap, vec3(uv, float(layer))).r ? 1.0 : 0.0;
#endif
}

// The depth a tap at offset o (texture units) from the lookup point compares against.
float tapDepth(float z, vec2 slope, vec2 o) {
#ifdef RECEIVER_PLANE
    return z + dot(slope, o);
#else
    return z;
#endif
}

// Light i's shadow coordinate of this fragment (clip space of the map, before the divide).
vec4 lookupCoord(int i, vec3 n) {
#ifdef NORMAL_OFFSET
    vec4 c = vShadowCoord[i];
    float texelWorld = uTexelWorld[i] * max(c.w, 0.0);
    float ndotl = clamp(dot(n, toLight(i, vWorldPos)), 0.0, 1.0);
    vec3 moved = vWorldPos + n * (uNormalOffset * texelWorld * (1.0 - ndotl));
    return uShadowMatrix[i] * vec4(moved, 1.0);
#else
    return vShadowCoord[i];
#endif
}

#ifdef KERNEL_ROTATED_GRID
float interleavedGradientNoise(vec2 pixel) {
#ifdef VULKAN
    pixel.y = uTargetHeight - pixel.y; // GL's lower-left origin: the same noise on both APIs
#endif
    return fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
}
#endif

float visibility(int layer, vec4 coord, vec2 slope) {
    // Behind a spot light (w <= 0) nothing is lit by it anyway; treat as lit so the term decides.
    if (coord.w <= 0.0) return 1.0;
    vec3 p = coord.xyz / coord.w;
    // Outside the light's frustum: not covered by the map, so no occluder was rendered there.
    if (any(lessThan(p.xy, vec2(0.0))) || any(greaterThan(p.xy, vec2(1.0))) || p.z > 1.0) return 1.0;
    vec2 texel = 1.0 / vec2(textureSize(uShadowMap, 0).xy);
#ifdef RECEIVER_PLANE
    p.z -= receiverQuantisation(slope, texel);
#endif
#if defined(KERNEL_POISSON) || defined(KERNEL_ROTATED_GRID)
#ifdef KERNEL_ROTATED_GRID
    float angle = 6.28318531 * interleavedGradientNoise(gl_FragCoord.xy);
    mat2 rotation = mat2(cos(angle), sin(angle), -sin(angle), cos(angle));
#else
    const mat2 rotation = mat2(1.0);
#endif
    float sum = 0.0;
    for (int k = 0; k < uKernelTaps; ++k) {
        vec2 o = (rotation * uKernel[k]) * texel;
        sum += shadowTap(layer, p.xy + o, tapDepth(p.z, slope, o));
    }
    return sum / float(uKernelTaps);
#else
    const float half_ = 0.5 * float(PCF_SIZE - 1);
    float sum = 0.0;
    for (int y = 0; y < PCF_SIZE; ++y)
        for (int x = 0; x < PCF_SIZE; ++x) {
            vec2 o = (vec2(x, y) - half_) * texel;
            sum += shadowTap(layer, p.xy + o, tapDepth(p.z, slope, o));
        }
    return sum / float(PCF_SIZE * PCF_SIZE);
#endif
}

void main() {
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing) n = -n;
    vec3 light = ambientLight();
    vec4 vis = vec4(1.0);
    for (int i = 0; i < LIGHT_COUNT; ++i) {
        vec4 coord = lookupCoord(i, n);
#ifdef RECEIVER_PLANE
        vec2 slope = receiverSlope(coord.xyz / coord.w); // before any branch: derivatives
#else
        vec2 slope = vec2(0.0);
#endif
        vis[i] = shadowApplies(i, vColorId) ? contactLimited(i, visibility(i, coord, slope), vWorldPos, n)
                                            : 1.0;
        light += vis[i] * lightTerm(i, vWorldPos, n);
    }
    oColor = vec4(vColorId.rgb * light, 1.0);
    oVisibility = vis;
}
