// `volume` shadow-volume geometry (GPU Gems ch. 9, Listing 9-3). Two inputs:
//  - CPU silhouettes (default): the doubled vertex buffer, (x, y, z, 1) for the object and
//    (x, y, z, 0) for the copies the shader sends to infinity away from the light;
//  - VS_EXTRUSION (McGuire and Hughes 2003): every vertex carries the plane (N, dot(N, P0)) of the
//    face it stands for and is sent to infinity when that face points away from the light, so the
//    silhouette is found here instead of on the CPU. The test uses the plane, not this vertex's
//    position: all vertices of a face get the same inputs and agree even when the light grazes it.
// FINITE (section 9.6.1): extrude by the light's range instead of to infinity.
// PULLED (extrusion=compute): the doubled buffer's entries, fetched by the compute shader's choice.
// GPU_SILHOUETTES (extrusion=geometry): the vertices of triangles with adjacency, projected as they are
// and extruded, passed on with their face's normal and first vertex to volume/silhouette.geom.
#include "common/frame.glsl"

#ifdef VS_EXTRUSION
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec4 aFacePlane;
#elif defined(GPU_SILHOUETTES)
layout(location = 0) in vec4 aPosition;
layout(location = 1) in vec4 aNormal;
layout(location = 2) in vec4 aFirst;
layout(location = 0) out vec4 vExtruded; // the extruded copy, projected
layout(location = 1) out vec3 vNormal;
layout(location = 2) out vec3 vFirst;
#elif defined(PULLED)
// extrusion=compute: vertex i is the doubled entry uVertices[i] (volume/silhouette.comp's output), fetched
// here instead of by the vertex input (drawn without indices, see that file).
#ifdef VULKAN
layout(std430, set = 1, binding = 0) readonly buffer Vertices {
    uint uVertices[];
};
layout(std430, set = 1, binding = 1) readonly buffer Doubled {
    vec4 uDoubled[]; // every caster mesh's doubled entries (techniques/volume/GpuSilhouettesVulkan.h)
};
#define VERTEX_ID gl_VertexIndex
#else
layout(std430, binding = 2) readonly buffer Vertices {
    uint uVertices[];
};
layout(std430, binding = 4) readonly buffer Doubled {
    vec4 uDoubled[]; // the caster mesh's doubled vertex buffer
};
#define VERTEX_ID gl_VertexID
#endif
#else
layout(location = 0) in vec4 aPosition;
#endif
#include "volume/draw.glsl"
#include "volume/extrude.glsl"

void main() {
#ifdef VS_EXTRUSION
    // Listing 9-5 in plane form: dot(N, L.xyz - P0 L.w) = dot(N, L.xyz) - L.w dot(N, P0).
    bool back = dot(aFacePlane.xyz, uLightObject.xyz) - uLightObject.w * aFacePlane.w < 0.0;
    vec4 p = back ? extrude(aPosition) : vec4(aPosition, 1.0);
#elif defined(GPU_SILHOUETTES)
    // The face's own vertex (w = 1) and its extruded copy, both projected here as the CPU path's
    // vertex shader projects them (the geometry shader only chooses among them).
    vec4 p = aPosition;
    vExtruded = uViewProj * (uModel * extrude(aPosition.xyz));
    vNormal = aNormal.xyz;
    vFirst = aFirst.xyz;
#else
#ifdef PULLED
    const vec4 aPosition = uDoubled[uVertices[VERTEX_ID]];
#endif
    vec4 p = aPosition.w == 0.0 ? extrude(aPosition.xyz) : aPosition;
#endif
    gl_Position = uViewProj * (uModel * p);
}
