// The depth pass of a light's depth map: the casters seen from the light, depth only. Shared by the
// shadow-map family's flat maps and faces (techniques/shadowmap/) and any other technique that renders
// a light's depth (techniques/vulkan/VulkanDepthMapSet.h).
#include "common/instance.glsl"

#ifdef VULKAN
// One slot per light of a dynamic uniform buffer (techniques/vulkan/VulkanDepthMapSet.h).
layout(std140, set = 1, binding = 0) uniform LightPass {
    mat4 uLightViewProj;
};
#else
layout(location = 8) uniform mat4 uLightViewProj;
#endif

void main() { gl_Position = uLightViewProj * (instanceModel() * vec4(aPosition, 1.0)); }
