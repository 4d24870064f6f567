// `paraboloid` depth pass: casters into one hemisphere of the dual-paraboloid map (Brabec, Annen,
// Seidel 2002), the projection per vertex. Written homogeneously, (d.x, d.y, z (1 + d.z), 1 + d.z),
// so that the GL's clipping interpolates in clip space and a triangle crossing the hemisphere's plane
// is cut where the clip distance d.z is 0 (gl_ClipDistance[0]; the part behind belongs to the other
// half). The projection is non-linear, but the rasteriser joins the projected vertices with straight
// edges and interpolates depth linearly between them: a long straight edge, which should map to an
// arc, is a chord, and the middle of a large face, nearer to the light than its vertices, gets a
// depth too far (light leaks through it). The known limit of the method: tessellation matters
// (techniques/shadowmap/ParaboloidGL.h).
#include "common/instance.glsl"
#include "shadowmap/paraboloid_frame.glsl"

layout(location = 8) uniform vec4 uLight; // xyz: position; w: hemisphere (0 front, 1 back)
layout(location = 12) uniform vec2 uNearFar;

out float gl_ClipDistance[1];

void main() {
    vec3 world = (instanceModel() * vec4(aPosition, 1.0)).xyz;
    vec3 p = paraboloidFrame(world - uLight.xyz, int(uLight.w));
    float dist = length(p);
    vec3 d = dist > 0.0 ? p / dist : vec3(0.0, 0.0, 1.0);
    float w = 1.0 + d.z;
    float z = 2.0 * paraboloidDepth(dist, uNearFar) - 1.0;
    gl_Position = vec4(d.xy, z * w, w);
    gl_ClipDistance[0] = d.z;
}
