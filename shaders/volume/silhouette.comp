// `volume` extrusion=compute: the chapter's closed-mesh volume (techniques/volume/ShadowVolumeMesh.h,
// buildVolume) built per face, one invocation each, as the vertices of its triangles: copies of the
// caster's doubled vertex buffer's entries (the corner with w = 1, or w = 0 for the copy that
// volume/extrude.vert sends to infinity), drawn without indices. Each invocation reserves its vertices
// with one atomicAdd on its draw's indirect command's count, so the marking pass draws exactly what was
// built (glDrawArraysIndirect, vkCmdDrawIndirect), and adds its triangles to the frame's device count
// (uTriangles, read back after the measured frames). The order in which invocations reserve is the
// device's, so the triangles' order varies between runs; drawn without indices, every count of the
// marking pass (vertex shader runs included, which an index order would change through the vertex
// cache) and its stencil result do not. Storage bindings 0-3 of set 0 on both APIs.
layout(local_size_x = 64) in;

#include "volume/silhouette.glsl"

#ifdef VULKAN
// techniques/volume/GpuSilhouettesVulkan.cpp's SilhouettePush: the same values as GL's uniforms.
layout(push_constant) uniform SilhouettePush {
    vec4 light;
    vec4 apex;
    uint flags, faceCount, draw, faceBase;
} uPush;
#define uLightObject uPush.light
#define uApex uPush.apex
#define uFlags uPush.flags
#define uFaceCount uPush.faceCount
#define uDraw uPush.draw
#define uFaceBase uPush.faceBase
#else
layout(location = 1) uniform vec4 uLightObject; // object space: (position, 1) or (towards light, 0)
layout(location = 3) uniform uint uFlags;       // techniques/volume/GpuVolumeFlags.h
layout(location = 4) uniform uint uFaceCount;
layout(location = 5) uniform uint uDraw;        // this caster's command in uCommands
layout(location = 6) uniform vec4 uApex;        // the mesh's vertex 0 with w = 0 (directional sides)
layout(location = 7) uniform uint uFaceBase;    // this mesh's first face in uFaces
#endif

layout(std430, binding = 0) buffer Count {
    uint uTriangles;
};
struct Face {
    uvec4 vertices;   // welded indices, counter-clockwise
    uvec4 neighbours; // the face across (v0, v1), (v1, v2), (v2, v0)
    vec4 normal;      // unnormalised, as ShadowVolumeMesh::faceNormals
    vec4 corners[3];  // the face's vertices, w = 1 (corners[0] the first vertex of Listing 9-5)
};
layout(std430, binding = 1) readonly buffer Faces {
    Face uFaces[];
};
layout(std430, binding = 2) writeonly buffer Vertices {
    vec4 uVertices[];
};
// The indirect draws' commands, 4 uints each (DrawArraysIndirectCommand, VkDrawIndirectCommand):
// count, instanceCount, first, baseInstance. count starts at 0 and grows here; first is this caster's
// region.
layout(std430, binding = 3) buffer Commands {
    uint uCommands[];
};

// Face f of this mesh (its faces and neighbours are numbered from 0; Vulkan keeps every mesh's faces in
// one buffer, GL one buffer per mesh at base 0).
bool back(uint f) {
    return backFacing(uFaces[uFaceBase + f].normal.xyz, uFaces[uFaceBase + f].corners[0].xyz, uLightObject);
}

void main() {
    const uint f = gl_GlobalInvocationID.x;
    if (f >= uFaceCount) return;
    const bool isBack = back(f);
    const bool cap = isBack ? (uFlags & SV_DARK_CAP) != 0u : (uFlags & SV_LIGHT_CAP) != 0u;
    uint silhouette = 0u; // bit k: edge k is a silhouette this face owns
    if (isBack && (uFlags & SV_SIDES) != 0u)
        for (uint k = 0u; k < 3u; ++k)
            if (!back(uFaces[uFaceBase + f].neighbours[k])) silhouette |= 1u << k;
    const uint sides = bitCount(silhouette);
    const uint triangles = (cap ? 1u : 0u) + sides * sideTriangles(uFlags);
    if (triangles == 0u) return;
    atomicAdd(uTriangles, triangles);
    uint at = uCommands[4u * uDraw + 2u] + atomicAdd(uCommands[4u * uDraw], 3u * triangles);
    vec4 near[3], far[3]; // the doubled buffer's entries of the corners: w = 1 and w = 0
    for (uint k = 0u; k < 3u; ++k) {
        near[k] = vec4(uFaces[uFaceBase + f].corners[k].xyz, 1.0);
        far[k] = vec4(near[k].xyz, 0.0);
    }
    if (cap)
        for (uint k = 0u; k < 3u; ++k) uVertices[at++] = isBack ? far[k] : near[k];
    for (uint k = 0u; k < 3u; ++k) {
        if ((silhouette & (1u << k)) == 0u) continue;
        const uint b = (k + 1u) % 3u;
        // ShadowVolumeMesh's pushSide: (a, b, b'), (a, b', a'), or (a, b, L') with L' the mesh's first
        // w = 0 vertex, as the CPU's index n.
        uVertices[at++] = near[k];
        uVertices[at++] = near[b];
        if ((uFlags & SV_DIRECTIONAL) != 0u) {
            uVertices[at++] = uApex;
            continue;
        }
        uVertices[at++] = far[b];
        uVertices[at++] = near[k];
        uVertices[at++] = far[b];
        uVertices[at++] = far[k];
    }
}
