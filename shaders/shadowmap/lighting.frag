// `shadowmap` lighting pass: compare each fragment's light-space depth with the shadow map
// (Williams 1978; the thesis section 2.4). HW_COMPARE uses a depth-compare sampler with bilinear
// filtering of the comparison results (the "hardware PCF" of every GPU since the GeForce 3); without
// it, nearest depth fetches are compared in the shader. PCF_SIZE x PCF_SIZE taps, one texel apart.
#include "common/frame.glsl"
#include "common/lighting.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vColorId;
in vec4 vShadowCoord[LIGHT_COUNT];
layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oVisibility;

#ifdef HW_COMPARE
layout(binding = 0) uniform sampler2DArrayShadow uShadowMap;
#else
layout(binding = 0) uniform sampler2DArray uShadowMap;
#endif

float shadowTap(int layer, vec2 uv, float depth) {
#ifdef HW_COMPARE
    return texture(uShadowMap, vec4(uv, float(layer), depth));
#else
    return depth <= texture(uShadowMap, vec3(uv, float(layer))).r ? 1.0 : 0.0;
#endif
}

float visibility(int layer, vec4 coord) {
    // Behind a spot light (w <= 0) nothing is lit by it anyway; treat as lit so the term decides.
    if (coord.w <= 0.0) return 1.0;
    vec3 p = coord.xyz / coord.w;
    // Outside the light's frustum: not covered by the map, so no occluder was rendered there.
    if (any(lessThan(p.xy, vec2(0.0))) || any(greaterThan(p.xy, vec2(1.0))) || p.z > 1.0) return 1.0;
    vec2 texel = 1.0 / vec2(textureSize(uShadowMap, 0).xy);
    const float half_ = 0.5 * float(PCF_SIZE - 1);
    float sum = 0.0;
    for (int y = 0; y < PCF_SIZE; ++y)
        for (int x = 0; x < PCF_SIZE; ++x)
            sum += shadowTap(layer, p.xy + (vec2(x, y) - half_) * texel, p.z);
    return sum / float(PCF_SIZE * PCF_SIZE);
}

void main() {
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing) n = -n;
    vec3 light = uAmbient.rgb;
    vec4 vis = vec4(1.0);
    for (int i = 0; i < LIGHT_COUNT; ++i) {
        vis[i] = visibility(i, vShadowCoord[i]);
        light += vis[i] * lightTerm(i, vWorldPos, n);
    }
    oColor = vec4(vColorId.rgb * light, 1.0);
    oVisibility = vis;
}
