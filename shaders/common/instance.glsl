// Per-instance data as the Submitter provides it (techniques/gl/ and techniques/vulkan/):
//  - immediate, displaylist, retained: uniforms at fixed locations, set before each draw;
//  - instanced (SB_INSTANCED): per-instance vertex attributes (divisor 1);
//  - Vulkan per-instance draws (VULKAN): the push constants of common/push.glsl.
// Instances have uniform scale only, so mat3(model) transforms normals up to length.
// The colour's w is the 1-based object id, negative for an instance that receives no shadow
// (shadowSignedId in scenes/DrawSet.h): read the id as abs(w).
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
#ifdef SB_INSTANCED
layout(location = 4) in mat4 aModel; // locations 4..7
layout(location = 8) in vec4 aColorId;
mat4 instanceModel() { return aModel; }
vec4 instanceColorId() { return aColorId; }
#elif defined(VULKAN)
// Vulkan per-instance draws: the instance in the push constants (common/push.glsl).
#include "common/push.glsl"
mat4 instanceModel() { return uPush.model; }
vec4 instanceColorId() { return uPush.colorId; }
#else
layout(location = 0) uniform mat4 uModel;
layout(location = 4) uniform vec4 uColorId;
mat4 instanceModel() { return uModel; }
vec4 instanceColorId() { return uColorId; }
#endif
