// `evsm` lighting pass: exponential variance shadow maps (Lauritzen and McCool 2008, Layered Variance Shadow
// Maps, GI, the section on the exponential warp): the bilinearly filtered (and blurred) moments of the warped
// depths around the receiver, Chebyshev's bound in the positive warp's space and, with EVSM_NEGATIVE
// (`components=4`), in the negative warp's, the smaller of the two (shadowmap/evsm.glsl), then vsm's
// light-bleeding reduction. EVSM_EXPONENTS is vec2(c+, c-), as in the depth pass (shadowmap/moments.frag).
#include "common/frame.glsl"
#include "common/lighting.glsl"
#include "common/contact_shadow.glsl"
#include "shadowmap/evsm.glsl"
#include "shadowmap/light_depth.glsl"

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

#ifdef EVSM_NEGATIVE
const bool kNegativeWarp = true;
#else
const bool kNegativeWarp = false;
#endif

float visibility(int layer, vec4 coord) {
    vec2 uv;
    if (!mapCoordinate(coord, uMapMargin, uv)) return 1.0;
    float t = lightDepth(uDepthPlane[layer], uDepthPoint[layer], vWorldPos);
    vec4 moments = texture(uMoments, vec3(uv, float(layer)));
    return evsmVisibility(moments, t, EVSM_EXPONENTS, kNegativeWarp, uMinVariance, uBleedReduction);
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
