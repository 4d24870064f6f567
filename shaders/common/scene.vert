// Vertex stage shared by the lit passes of most techniques: world position, normal, colour, and under
// SB_VERTEX_LIGHTING (`--lighting vertex`) each light's term at the vertex (common/lighting.glsl).
// Every fragment stage it feeds includes common/lighting.glsl before its own varyings, so that on
// Vulkan, which numbers varyings in declaration order, the terms come first on both sides.
#include "common/frame.glsl"
#include "common/instance.glsl"
#include "common/lighting.glsl"

out vec3 vWorldPos;
out vec3 vNormal;
out vec4 vColorId;
#ifdef SB_EYE_RELATIVE_POSITION
// The world position minus the eye's, for a fragment stage that takes the triangle's plane from screen-space
// derivatives (raytraced/lighting.frag): small numbers that keep their precision where world coordinates
// are large (at 1e5 a float is 0.0078 apart, a quarter of a pixel's footprint there).
out vec3 vEyeRelativePos;
#endif
#ifdef SHADOW_MAP
#ifdef VULKAN
// The head of shadowmap/lighting.frag's block (techniques/shadowmap/ShadowMapVulkan.h).
layout(std140, set = 1, binding = 0) uniform ShadowMapBlock {
    mat4 uShadowMatrix[LIGHT_COUNT];
};
#else
layout(location = 8) uniform mat4 uShadowMatrix[LIGHT_COUNT]; // bias * lightProj * lightView
#endif
out vec4 vShadowCoord[LIGHT_COUNT];
#endif

void main() {
    mat4 model = instanceModel();
    vec4 world = model * vec4(aPosition, 1.0);
    vWorldPos = world.xyz;
    vNormal = mat3(model) * aNormal;
    vColorId = instanceColorId();
#ifdef SB_EYE_RELATIVE_POSITION
    vEyeRelativePos = world.xyz - uEye.xyz;
#endif
#ifdef SHADOW_MAP
    for (int i = 0; i < LIGHT_COUNT; ++i) vShadowCoord[i] = uShadowMatrix[i] * world;
#endif
#ifdef SB_VERTEX_LIGHTING
    writeVertexLighting(world.xyz, normalize(vNormal));
#endif
    gl_Position = uViewProj * world;
}
