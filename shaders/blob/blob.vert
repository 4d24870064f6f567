// `blob`: one quad per blob (4-vertex strip, instanced), spanning the ellipse's bounding rectangle on the
// ground. Records as BlobTechnique::Blob (std430, 3 vec4 each).
#include "common/frame.glsl"

layout(std430, binding = 4) readonly buffer Blobs { vec4 uBlobs[]; };
out vec2 vCorner;            // ellipse coordinates: r = length(vCorner) = 1 on the ellipse
out vec3 vWorld;
flat out vec3 vParams;       // opacity, light index, softness

void main() {
    vec4 c = uBlobs[3 * gl_InstanceID], u = uBlobs[3 * gl_InstanceID + 1], v = uBlobs[3 * gl_InstanceID + 2];
    vCorner = vec2((gl_VertexID & 1) != 0 ? 1.0 : -1.0, (gl_VertexID & 2) != 0 ? 1.0 : -1.0);
    vWorld = c.xyz + vCorner.x * u.xyz + vCorner.y * v.xyz;
    vParams = vec3(c.w, u.w, v.w);
    gl_Position = uViewProj * vec4(vWorld, 1.0);
}
