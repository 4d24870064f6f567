// `esm` lighting pass: exponential shadow maps (Annen, Mertens, Seidel, Bekaert, Kautz 2008, Exponential
// Shadow Maps, section 3, equations 3-5): with the map's filtered exp(c d_occ), a receiver at depth t gets
//     visibility = clamp(exp(-c t) * filter(exp(c d_occ)), 0, 1),
// exact for a receiver behind its occluders and a smooth step of steepness c at the contact. The map holds
// depth d (Salvi 2008, Rendering Filtered Shadows with Exponential Shadow Maps, ShaderX6: filtering in log
// space), blurred into log(sum w exp(c d)) / c by common/blur.frag, so the bilinear lookup is done here
// in log space too: the four texels' weighted exp(c (d_k - m)), m the largest depth among the taps that
// count, so no term exceeds 1 and the sum is at least that tap's weight; then
//     visibility = exp(min(c (m - t) + log(sum), 0)),
// finite and in [0, 1] at every exponent (exp(c d) itself overflows a float from c d = 88.7 on).
#include "common/frame.glsl"
#include "common/lighting.glsl"
#include "common/contact_shadow.glsl"
#include "shadowmap/esm.glsl"
#include "shadowmap/light_depth.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vColorId;
in vec4 vShadowCoord[LIGHT_COUNT];
layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oVisibility;

#ifdef VULKAN
// Set 1 (techniques/shadowmap/VulkanMomentMaps.h): the uniforms GL sets by location, in one block whose
// head common/scene.vert reads, and the depths.
layout(std140, set = 1, binding = 0) uniform ShadowMapBlock {
    mat4 uShadowMatrix[LIGHT_COUNT];
    vec4 uDepthPlane[LIGHT_COUNT];
    vec4 uDepthPoint[LIGHT_COUNT];
    float uMapMargin;
    float uExponent;
};
layout(set = 1, binding = 1) uniform sampler2DArray uDepths;
#else
layout(binding = 0) uniform sampler2DArray uDepths;
layout(location = 32) uniform vec4 uDepthPlane[LIGHT_COUNT];
layout(location = 36) uniform vec4 uDepthPoint[LIGHT_COUNT];
layout(location = 44) uniform float uMapMargin; // texture coordinates
layout(location = 40) uniform float uExponent;
#endif

// Bilinear filtering of exp(c d) in log space: the texels and weights GL_LINEAR would use.
float exponentialLookup(int layer, vec2 uv, float t) {
    vec2 f = fract(uv * vec2(textureSize(uDepths, 0).xy) - 0.5);
    // textureGather's order: (i0, j1), (i1, j1), (i1, j0), (i0, j0).
    vec4 d = textureGather(uDepths, vec3(uv, float(layer)), 0);
    vec4 w = vec4((1.0 - f.x) * f.y, f.x * f.y, f.x * (1.0 - f.y), (1.0 - f.x) * (1.0 - f.y));
    return exponentialVisibility(d, w, t, uExponent);
}

float visibility(int layer, vec4 coord) {
    vec2 uv;
    if (!mapCoordinate(coord, uMapMargin, uv)) return 1.0;
    float t = lightDepth(uDepthPlane[layer], uDepthPoint[layer], vWorldPos);
    return exponentialLookup(layer, uv, t);
}

void main() {
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing) n = -n;
    vec3 light = ambientLight();
    vec4 vis = vec4(1.0);
    for (int i = 0; i < LIGHT_COUNT; ++i) {
        vis[i] = shadowApplies(i, vColorId)
                     ? contactLimited(i, visibility(i, vShadowCoord[i]), vWorldPos, n)
                     : 1.0;
        light += vis[i] * lightTerm(i, vWorldPos, n);
    }
    oColor = vec4(vColorId.rgb * light, 1.0);
    oVisibility = vis;
}
