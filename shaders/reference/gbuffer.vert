// `reference` G-buffer pass: the world position and object id of every visible surface. The position
// arithmetic is that of common/scene.vert (model * position, then the view-projection), so that the
// G-buffer's pixels are the lighting pass's pixels.
#include "common/instance.glsl"

#ifdef VULKAN
// The frame block the lighting passes draw with (its viewProj already in Vulkan's clip space,
// techniques/vulkan/VulkanFrameBlock.h): the same matrix, so the same pixels.
#include "common/frame.glsl"
#define uGBufferViewProj uViewProj
#else
layout(location = 8) uniform mat4 uGBufferViewProj; // the harness camera's proj * view
#endif

out vec3 vWorldPos;      // smooth: perspective-correct, the surface point under the pixel centre
flat out float vObjectId; // Instance::objectId, 1-based

void main() {
    mat4 model = instanceModel();
    vec4 world = model * vec4(aPosition, 1.0);
    vWorldPos = world.xyz;
    vObjectId = abs(instanceColorId().w);
    gl_Position = uGBufferViewProj * world;
}
