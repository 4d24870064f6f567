// `paraboloid` depth pass: casters into one hemisphere of the dual-paraboloid map (Brabec, Annen,
// Seidel 2002), the projection per vertex (paraboloidClip, paraboloid_frame.glsl). The projection is
// non-linear, but the rasteriser joins the projected vertices with straight edges and interpolates
// depth linearly between them: a long straight edge, which should map to an arc, is a chord, and the
// middle of a large face, nearer to the light than its vertices, gets a depth too far (light leaks
// through it). So only casters whose edges span a small angle seen from the light take this stage
// alone; the others go through paraboloid_split.geom (techniques/shadowmap/ParaboloidGL.h).
#include "common/instance.glsl"
#include "shadowmap/paraboloid_frame.glsl"

#ifdef VULKAN
// One slot per hemisphere of a dynamic uniform buffer (techniques/shadowmap/ParaboloidVulkan.h).
layout(std140, set = 1, binding = 0) uniform ParaboloidPass {
    vec4 uLight; // xyz: position; w: hemisphere (0 front, 1 back)
    vec2 uNearFar;
    float uMaxAngle;  // radians a segment may span (paraboloid_split.geom)
    float uBeyondRim; // the clip plane's offset behind the hemisphere's
};
#else
layout(location = 8) uniform vec4 uLight; // xyz: position; w: hemisphere (0 front, 1 back)
layout(location = 12) uniform vec2 uNearFar;
layout(location = 14) uniform float uBeyondRim; // the clip plane's offset behind the hemisphere's
#endif

out float gl_ClipDistance[1];

void main() {
    vec3 world = (instanceModel() * vec4(aPosition, 1.0)).xyz;
    gl_Position = paraboloidClip(world - uLight.xyz, int(uLight.w), uNearFar, uBeyondRim, gl_ClipDistance[0]);
}
