// `blob`: one quad per blob (4-vertex strip, instanced), spanning the ellipse's bounding rectangle on the
// ground. Records as BlobTechnique::Blob (std430, 3 vec4 each).
#include "common/frame.glsl"

#ifdef VULKAN
// Set 1 (techniques/blob/BlobVulkan.h): the blob records; Vulkan's names of the draw's indices (no
// base instance or vertex is used, so they count from 0 as GL's do).
layout(std430, set = 1, binding = 0) readonly buffer Blobs { vec4 uBlobs[]; };
#define SB_INSTANCE gl_InstanceIndex
#define SB_VERTEX gl_VertexIndex
#else
layout(std430, binding = 4) readonly buffer Blobs { vec4 uBlobs[]; };
#define SB_INSTANCE gl_InstanceID
#define SB_VERTEX gl_VertexID
#endif
out vec2 vCorner;            // ellipse coordinates: r = length(vCorner) = 1 on the ellipse
out vec3 vWorld;
flat out vec3 vParams;       // opacity, light index, softness

void main() {
    vec4 c = uBlobs[3 * SB_INSTANCE], u = uBlobs[3 * SB_INSTANCE + 1], v = uBlobs[3 * SB_INSTANCE + 2];
    vCorner = vec2((SB_VERTEX & 1) != 0 ? 1.0 : -1.0, (SB_VERTEX & 2) != 0 ? 1.0 : -1.0);
    vWorld = c.xyz + vCorner.x * u.xyz + vCorner.y * v.xyz;
    vParams = vec3(c.w, u.w, v.w);
    gl_Position = uViewProj * vec4(vWorld, 1.0);
}
