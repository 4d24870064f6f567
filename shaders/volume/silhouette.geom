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

#include "volume/silhouette.glsl"

layout(location = 0) in vec4 vExtruded[]; // volume/extrude.vert: the extruded copy, projected
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

void emit(vec4 clip) {
    gl_Position = clip;
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
    // Nothing is projected here: volume/extrude.vert projected each vertex and its extruded copy as the
    // CPU path's vertex shader projects them, and this stage only chooses among them.
    const vec4 c[3] = vec4[3](gl_in[0].gl_Position, gl_in[2].gl_Position, gl_in[4].gl_Position);
    const vec4 e[3] = vec4[3](vExtruded[0], vExtruded[2], vExtruded[4]);
    if (!back && (uFlags & SV_LIGHT_CAP) != 0u) {
        triangle(c[0], c[1], c[2]);
        ++emitted;
    } else if (back && (uFlags & SV_DARK_CAP) != 0u) {
        triangle(e[0], e[1], e[2]);
        ++emitted;
    }
    if (back && (uFlags & SV_SIDES) != 0u) {
        for (int k = 0; k < 3; ++k) {
            if (backFacing(vNormal[2 * k + 1], vFirst[2 * k + 1], uLightObject)) continue;
            const int next = (k + 1) % 3;
            triangle(c[k], c[next], e[next]);
            if ((uFlags & SV_DIRECTIONAL) == 0u) triangle(c[k], e[next], e[k]);
            emitted += sideTriangles(uFlags);
        }
    }
    if (emitted != 0u) atomicAdd(uTriangles, emitted);
}
