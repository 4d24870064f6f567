// `planar` shadow polygons: each caster vertex flattened onto the receiver plane with the slides'
// matrix M = (P.L) I - L P^T (scenes/ReceiverPlane.h), in world space.
#include "common/frame.glsl"
#include "common/instance.glsl"

#ifdef VULKAN
// Set 1 (techniques/planar/PlanarVulkan.h): the uniforms GL sets by location, one record per flattening
// bound at its dynamic offset. The same block in both stages.
layout(std140, set = 1, binding = 0) uniform Flattening {
    mat4 uFlatten;
    vec4 uPlane;
    vec4 uLight;
    vec4 uAlbedoLight;
    float uDarkness;
};
#else
layout(location = 8) uniform mat4 uFlatten; // M for this plane and light
layout(location = 12) uniform vec4 uPlane;  // P = (n, d): n.x + d = 0
layout(location = 13) uniform vec4 uLight;  // L: (position, 1) or (-direction, 0)
#endif
out vec4 vFlat;                              // homogeneous world position on the plane

void main() {
    vec4 world = instanceModel() * vec4(aPosition, 1.0);
    vec4 flattened = uFlatten * world;
#ifdef GUARDS
    // The slides' wrong shadows and anti-shadows. The homogeneous result goes to the rasteriser
    // undivided, so a vertex beyond a point light (w < 0) is clipped like any point behind the eye
    // rather than divided through infinity. Both distances are linear in the vertex: exact clips.
    // 1. Occluder parts behind the receiver cannot shadow its front.
    gl_ClipDistance[0] = dot(uPlane, world);
    // 2. w of M v is (P.L) - (P.v) L.w: for a point light, the light's height over the plane minus the
    //    vertex's. A margin of 1e-4 (P.L) stops the projection at 1e4 times the vertex's offset
    //    instead of at infinity. Directional lights have w = P.L > 0 everywhere.
    gl_ClipDistance[1] = flattened.w - 1e-4 * dot(uPlane, uLight);
    vFlat = flattened;
    gl_Position = uViewProj * flattened;
#else
    // Unguarded: the slides' per-vertex form, v' divided out in the vertex shader. Vertices behind the
    // receiver flatten onto it (wrong shadows); vertices beyond the light (w < 0) land on the far side
    // of it (anti-shadows); a light behind the plane casts onto its front.
    vec3 v = flattened.xyz / flattened.w;
    vFlat = vec4(v, 1.0);
    gl_Position = uViewProj * vec4(v, 1.0);
#endif
}
