// A volume draw's values (volume/extrude.vert and volume/silhouette.geom): on GL uniforms, on Vulkan the
// push constants (common/push.glsl; techniques/volume/VolumeVulkan.h): model, the object-space light in
// vec, the FINITE extrusion length's bits in ints.y and the GPU silhouette flags in ints.z.
#ifdef VULKAN
#include "common/push.glsl"
#define uModel uPush.model
#define uLightObject uPush.vec
#define uRange intBitsToFloat(uPush.ints.y)
#define uFlags uint(uPush.ints.z)
#else
layout(location = 0) uniform mat4 uModel;
layout(location = 1) uniform vec4 uLightObject; // object space: (position, 1) or (towards light, 0)
layout(location = 2) uniform float uRange;       // FINITE: object-space extrusion length
layout(location = 3) uniform uint uFlags;        // GPU silhouettes: techniques/volume/GpuVolumeFlags.h
#endif
