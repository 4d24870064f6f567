// `shadowmap` depth pass: casters seen from light LIGHT_INDEX (uniform). Depth only.
#include "common/instance.glsl"

#ifdef VULKAN
// One slot per light of a dynamic uniform buffer (techniques/shadowmap/ShadowMapVulkan.h).
layout(std140, set = 1, binding = 0) uniform LightPass {
    mat4 uLightViewProj;
};
#else
layout(location = 8) uniform mat4 uLightViewProj;
#endif

void main() { gl_Position = uLightViewProj * (instanceModel() * vec4(aPosition, 1.0)); }
