// `vsm` lighting pass: variance shadow maps (Donnelly and Lauritzen 2006, Variance Shadow Maps, section 3,
// equation 5; Lauritzen 2007, GPU Gems 3 ch. 8, Listings 8-2 and 8-4). The bilinearly filtered (and
// blurred) moments M1 = E[d], M2 = E[d^2] around the receiver give mean mu = M1 and variance
// sigma^2 = max(M2 - M1^2, uMinVariance); for a receiver at depth t > mu, Chebyshev's one-tailed
// inequality bounds the fraction of the filter region at depth >= t, the lit fraction:
//     p_max = sigma^2 / (sigma^2 + (t - mu)^2),
// and t <= mu is lit (1). Light bleeding reduction (section 8.4.3): linstep(uBleedReduction, 1, p) cuts the
// bound's [0, amount] tail (where overlapping occluders leave a halo) and rescales the rest.
#include "common/frame.glsl"
#include "common/lighting.glsl"
#include "common/contact_shadow.glsl"
#include "shadowmap/light_depth.glsl"
#include "shadowmap/vsm.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vColorId;
in vec4 vShadowCoord[LIGHT_COUNT];
layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oVisibility;

#ifdef VULKAN
// Set 1 (techniques/shadowmap/VulkanMomentMaps.h): the uniforms GL sets by location, in one block whose
// head common/scene.vert reads, and the moments.
layout(std140, set = 1, binding = 0) uniform ShadowMapBlock {
    mat4 uShadowMatrix[LIGHT_COUNT];
    vec4 uDepthPlane[LIGHT_COUNT];
    vec4 uDepthPoint[LIGHT_COUNT];
    float uMapMargin;
    float uMinVariance;
    float uBleedReduction;
};
layout(set = 1, binding = 1) uniform sampler2DArray uMoments;
#else
layout(binding = 0) uniform sampler2DArray uMoments;
layout(location = 32) uniform vec4 uDepthPlane[LIGHT_COUNT];
layout(location = 36) uniform vec4 uDepthPoint[LIGHT_COUNT];
layout(location = 44) uniform float uMapMargin; // texture coordinates
layout(location = 40) uniform float uMinVariance;
layout(location = 41) uniform float uBleedReduction;
#endif

float visibility(int layer, vec4 coord) {
    vec2 uv;
    if (!mapCoordinate(coord, uMapMargin, uv)) return 1.0;
    float t = lightDepth(uDepthPlane[layer], uDepthPoint[layer], vWorldPos);
    vec2 moments = texture(uMoments, vec3(uv, float(layer))).rg;
    return reduceLightBleeding(chebyshevUpperBound(moments, t, uMinVariance), uBleedReduction);
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
