// `msm` lighting pass: moment shadow maps (Peters and Klein 2015, Moment Shadow Mapping, I3D): the bilinearly
// filtered (and blurred) four moments around the receiver, de-quantised with MSM_QUANTIZED (the 16-bit
// unorm map; shadowmap/msm.glsl), the Hamburger four-moment reconstruction with moment bias uMomentBias gives
// the fraction in front of the receiver; visibility is one minus it, then vsm's light-bleeding reduction
// (shadowmap/vsm.glsl; 0 by default: the four moments' bound is tight where vsm's two leak).
#include "common/frame.glsl"
#include "common/lighting.glsl"
#include "common/contact_shadow.glsl"
#include "shadowmap/light_depth.glsl"
#include "shadowmap/msm.glsl"
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
    float uMomentBias;
    float uBleedReduction;
};
layout(set = 1, binding = 1) uniform sampler2DArray uMoments;
#else
layout(binding = 0) uniform sampler2DArray uMoments;
layout(location = 32) uniform vec4 uDepthPlane[LIGHT_COUNT];
layout(location = 36) uniform vec4 uDepthPoint[LIGHT_COUNT];
layout(location = 44) uniform float uMapMargin; // texture coordinates
layout(location = 40) uniform float uMomentBias;
layout(location = 41) uniform float uBleedReduction;
#endif

float visibility(int layer, vec4 coord) {
    vec2 uv;
    if (!mapCoordinate(coord, uMapMargin, uv)) return 1.0;
    float t = lightDepth(uDepthPlane[layer], uDepthPoint[layer], vWorldPos);
    vec4 b = texture(uMoments, vec3(uv, float(layer)));
#ifdef MSM_QUANTIZED
    b = msmDequantize(b);
#endif
    return reduceLightBleeding(1.0 - hamburger4(b, t, uMomentBias), uBleedReduction);
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
