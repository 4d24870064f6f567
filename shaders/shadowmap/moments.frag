// Depth pass of the filterable shadow maps: writes only what the map stores, the depth test keeping the
// nearest caster.
// VSM (Donnelly and Lauritzen 2006, Variance Shadow Maps, section 3; Lauritzen 2007, GPU Gems 3 ch. 8,
// Listing 8-1): the moments (d, d^2), the second biased by the depth's variation over the texel
// (0.25 (ddx(d)^2 + ddy(d)^2)), so a sloped surface does not shadow itself after filtering.
// EVSM (Lauritzen and McCool 2008, Layered Variance Shadow Maps, the exponential warp): the moments of the
// warped depths, shadowmap/evsm.glsl's evsmMoments(); EVSM_EXPONENTS is vec2(c+, c-), compile-time constants
// of the technique's properties (techniques/shadowmap/Evsm.h).
// MSM (Peters and Klein 2015, Moment Shadow Mapping): the four power moments (d, d^2, d^3, d^4), with
// MSM_QUANTIZED through the paper's quantisation transform for a 16-bit unorm target (shadowmap/msm.glsl).
// Otherwise (ESM, Salvi 2008's log-space form): d itself; the exponential is taken when filtering.
#include "shadowmap/light_depth.glsl"
#if defined(EVSM_EXPONENTS)
#include "shadowmap/evsm.glsl"
#elif defined(MSM)
#include "shadowmap/msm.glsl"
#endif

#ifdef VULKAN
// The light's slot (shadowmap/moments.vert).
layout(std140, set = 1, binding = 0) uniform LightPass {
    mat4 uLightViewProj;
    vec4 uDepthPlane;
    vec4 uDepthPoint;
};
#else
layout(location = 32) uniform vec4 uDepthPlane;
layout(location = 36) uniform vec4 uDepthPoint;
#endif
in vec3 vWorldPos;
layout(location = 0) out vec4 oMoments;

void main() {
    float d = lightDepth(uDepthPlane, uDepthPoint, vWorldPos);
#ifdef VSM
    float dx = dFdx(d), dy = dFdy(d);
    oMoments = vec4(d, d * d + 0.25 * (dx * dx + dy * dy), 0.0, 0.0);
#elif defined(EVSM_EXPONENTS)
    oMoments = evsmMoments(d, vec2(dFdx(d), dFdy(d)), EVSM_EXPONENTS);
#elif defined(MSM) && defined(MSM_QUANTIZED)
    oMoments = msmQuantize(msmMoments(d));
#elif defined(MSM)
    oMoments = msmMoments(d);
#else
    oMoments = vec4(d, 0.0, 0.0, 0.0);
#endif
}
