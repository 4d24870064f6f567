// `paraboloid` lighting pass: a point light's visibility from its two paraboloid halves (Brabec,
// Annen, Seidel 2002), computed per fragment: the hemisphere is the sign of the light-to-fragment
// vector along the front axis, the map coordinates are the paraboloid projection of its direction
// and the reference depth its length, as the depth pass wrote them (paraboloid_frame.glsl). Both
// halves of light i are layers `layer` (front) and `layer + 1` (back) of the 2D depth array that
// also holds the spot and directional maps. PCF taps step one texel in map space.
#include "common/frame.glsl"
#include "common/lighting.glsl"
#include "common/contact_shadow.glsl"
#include "shadowmap/omni_lighting.glsl"
#include "shadowmap/paraboloid_frame.glsl"

#ifdef OMNI_MAPS
#ifndef FLAT_MAPS
#ifdef VULKAN
layout(set = 1, binding = 1) uniform sampler2DArrayShadow uFlatMaps;
#else
layout(binding = 0) uniform sampler2DArrayShadow uFlatMaps;
#endif
#endif

float omniVisibility(int light, int layer, vec3 v, vec2 nearFar) {
    float dist = length(v);
    if (dist <= nearFar.x || dist >= nearFar.y) return 1.0; // no caster was rendered there
    int half_ = paraboloidFrame(v, 0).z >= 0.0 ? 0 : 1;
    vec3 d = paraboloidFrame(v, half_) / dist;
    vec2 uv = 0.5 * paraboloidProject(d) + 0.5;
    float depth = paraboloidDepth(dist, nearFar);
    vec2 texel = 1.0 / vec2(textureSize(uFlatMaps, 0).xy);
    const float half_w = 0.5 * float(PCF_SIZE - 1);
    float sum = 0.0;
    for (int y = 0; y < PCF_SIZE; ++y)
        for (int x = 0; x < PCF_SIZE; ++x)
            sum += texture(uFlatMaps, vec4(uv + (vec2(x, y) - half_w) * texel, float(layer + half_), depth));
    return sum / float(PCF_SIZE * PCF_SIZE);
}
#else
float omniVisibility(int light, int layer, vec3 v, vec2 nearFar) {
    return 1.0;
}
#endif
