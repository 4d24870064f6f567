// Depth pass of the filterable shadow maps (`vsm`, `esm`): casters seen from one light. The world position
// goes to the fragment stage, which computes the linear depth it stores (shadowmap/light_depth.glsl).
#include "common/instance.glsl"

#ifdef VULKAN
// One slot per light of a dynamic uniform buffer, read by both stages (techniques/shadowmap/
// VulkanMomentMaps.h).
layout(std140, set = 1, binding = 0) uniform LightPass {
    mat4 uLightViewProj;
    vec4 uDepthPlane;
    vec4 uDepthPoint;
};
#else
layout(location = 8) uniform mat4 uLightViewProj;
#endif
out vec3 vWorldPos;

void main() {
    vec4 world = instanceModel() * vec4(aPosition, 1.0);
    vWorldPos = world.xyz;
    gl_Position = uLightViewProj * world;
}
