// Vulkan's per-draw data (one push-constant block, 112 bytes, within the 128 every device offers),
// shared by every stage that reads it (techniques/vulkan/VulkanSubmitter.h, VulkanPush): the instance
// of a per-instance draw (what GL sets as uniforms at locations 0 and 4) and a few technique values
// per pass (a light index, a volume's object-space light). GL programs never see it.
#ifdef VULKAN
layout(push_constant) uniform Push {
    mat4 model;    // per-instance draws: the instance's model matrix
    vec4 colorId;  // per-instance draws: colour rgb, signed 1-based object id
    ivec4 ints;    // the technique's: x light index
    vec4 vec;      // the technique's: a volume's object-space light
} uPush;
#endif
