// `cubemap` lighting pass: a point light's visibility from its depth cube map (Gerasimov 2004,
// Omnidirectional Shadow Mapping, GPU Gems ch. 12; Williams 1978). The vector from the light to the
// fragment selects the face as the GL does (its major axis); the face was rendered with a 90-degree
// perspective camera, so the depth it stored for this direction is that camera's depth of the
// fragment, which depends only on the major-axis distance z: (f + n)/(f - n) - 2fn/((f - n) z),
// mapped to [0, 1] (techniques/shadowmap/CubeFaces.h, windowDepth). Gerasimov stores the distance to
// the light in a float colour cube map instead; the per-face depth keeps the hardware depth compare,
// its bilinear filtering and glPolygonOffset's slope-scaled bias. Seamless cube filtering is on
// (GL_TEXTURE_CUBE_MAP_SEAMLESS), so bilinear footprints and PCF taps cross face edges.
#include "common/frame.glsl"
#include "common/lighting.glsl"
#include "common/contact_shadow.glsl"
#include "shadowmap/omni_lighting.glsl"

#ifdef OMNI_MAPS
#ifdef VULKAN
layout(set = 1, binding = 2) uniform samplerCubeArrayShadow uCubeMaps;
#else
layout(binding = 1) uniform samplerCubeArrayShadow uCubeMaps;
#endif

float omniVisibility(int light, int cube, vec3 d, vec2 nearFar) {
    vec3 a = abs(d);
    float z = max(a.x, max(a.y, a.z));
    // Outside [near, far] along the face's axis no caster was rendered: nothing to compare against.
    if (z <= nearFar.x || z >= nearFar.y) return 1.0;
    float n = nearFar.x, f = nearFar.y;
    float depth = 0.5 * ((f + n) / (f - n) - 2.0 * f * n / ((f - n) * z)) + 0.5;
    // PCF taps step one texel (2z / resolution in direction units at the face) along the face's two
    // minor axes; a tap past the edge continues on the neighbouring face.
    // Same major axis as the GL's face selection (ties to x, then y).
    bool xMajor = a.x >= a.y && a.x >= a.z;
    bool yMajor = !xMajor && a.y >= a.z;
    vec3 u = xMajor ? vec3(0, 1, 0) : vec3(1, 0, 0);
    vec3 v = xMajor || yMajor ? vec3(0, 0, 1) : vec3(0, 1, 0);
    float texel = 2.0 * z / float(textureSize(uCubeMaps, 0).x);
    const float half_ = 0.5 * float(PCF_SIZE - 1);
    float sum = 0.0;
    for (int y = 0; y < PCF_SIZE; ++y)
        for (int x = 0; x < PCF_SIZE; ++x) {
            vec3 dir = d + ((float(x) - half_) * u + (float(y) - half_) * v) * texel;
            sum += texture(uCubeMaps, vec4(dir, float(cube)), depth);
        }
    return sum / float(PCF_SIZE * PCF_SIZE);
}
#else
float omniVisibility(int light, int cube, vec3 d, vec2 nearFar) {
    return 1.0;
}
#endif
