// `volume` extrusion=geometry: the chapter's closed-mesh volume (techniques/volume/ShadowVolumeMesh.h,
// buildVolume) built per face in a geometry shader from triangles with adjacency. Every vertex carries
// the plane data of a face (techniques/volume/VolumeMeshBuffers.h): the even slots 0, 2, 4 are this
// face's vertices with its normal and first vertex, odd slot 2k + 1 is the vertex opposite edge
// (2k, 2k + 2) in the face across it, with that face's normal and first vertex. So each face's
// classification is computed from the same numbers wherever it is needed: the face and its neighbours
// agree on every edge, and exactly one of a silhouette edge's two faces (the back one) emits its side.
// The triangles emitted are counted on the device (uTriangles, read back after the measured frames).
layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 21) out;

#include "common/frame.glsl"
#include "volume/silhouette.glsl"

layout(location = 0) in vec3 vPosition[];
layout(location = 1) in vec3 vNormal[];
layout(location = 2) in vec3 vFirst[];

#include "volume/draw.glsl"

#ifdef VULKAN
layout(std430, set = 1, binding = 0) buffer Count {
#else
layout(std430, binding = 0) buffer Count {
#endif
    uint uTriangles; // this frame's volume triangles (techniques/volume/VolumeGL.h)
};

#include "volume/extrude.glsl"

void emit(vec4 p) {
    gl_Position = uViewProj * (uModel * p);
    EmitVertex();
}

void triangle(vec4 a, vec4 b, vec4 c) {
    emit(a);
    emit(b);
    emit(c);
    EndPrimitive();
}

void main() {
    const bool back = backFacing(vNormal[0], vFirst[0], uLightObject);
    uint emitted = 0u;
    vec4 p[3] = vec4[3](vec4(vPosition[0], 1.0), vec4(vPosition[2], 1.0), vec4(vPosition[4], 1.0));
    if (!back && (uFlags & SV_LIGHT_CAP) != 0u) {
        triangle(p[0], p[1], p[2]);
        ++emitted;
    } else if (back && (uFlags & SV_DARK_CAP) != 0u) {
        triangle(extrude(p[0].xyz), extrude(p[1].xyz), extrude(p[2].xyz));
        ++emitted;
    }
    if (back && (uFlags & SV_SIDES) != 0u) {
        for (int k = 0; k < 3; ++k) {
            if (backFacing(vNormal[2 * k + 1], vFirst[2 * k + 1], uLightObject)) continue;
            const vec4 a = p[k], b = p[(k + 1) % 3];
            const vec4 bInf = extrude(b.xyz);
            triangle(a, b, bInf);
            if ((uFlags & SV_DIRECTIONAL) == 0u) triangle(a, bInf, extrude(a.xyz));
            emitted += sideTriangles(uFlags);
        }
    }
    if (emitted != 0u) atomicAdd(uTriangles, emitted);
}
