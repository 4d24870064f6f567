// `volume` extrusion=compute: the chapter's closed-mesh volume (techniques/volume/ShadowVolumeMesh.h,
// buildVolume) built per face, one invocation each, as the entries of the caster's doubled vertex buffer
// (w = 1 copies, then the w = 0 copies at + uVertexCount that volume/extrude.vert sends to infinity) its
// triangles' vertices are. The marking pass draws them without indices: volume/extrude.vert under PULLED
// fetches vertex i's entry through uVertices[i] (vertex pulling). Each invocation reserves its vertices
// with one atomicAdd on its draw's indirect command's count, so the marking pass draws exactly what was
// built (glDrawArraysIndirect, vkCmdDrawIndirect), and adds its triangles to the frame's device count
// (uTriangles, read back after the measured frames). The order in which invocations reserve is the
// device's and varies between runs; drawn without indices, no count of the marking pass changes with it
// (an index buffer would change the vertex shader runs through the vertex cache). Storage bindings 0-3
// of set 0 on both APIs.
layout(local_size_x = 64) in;

#include "volume/silhouette.glsl"

#ifdef VULKAN
// techniques/volume/GpuSilhouettesVulkan.cpp's SilhouettePush: the same values as GL's uniforms.
layout(push_constant) uniform SilhouettePush {
    vec4 light;
    uint flags, faceCount, draw, vertexCount, faceBase, vertexBase;
} uPush;
#define uLightObject uPush.light
#define uFlags uPush.flags
#define uFaceCount uPush.faceCount
#define uDraw uPush.draw
#define uVertexCount uPush.vertexCount
#define uFaceBase uPush.faceBase
#define uVertexBase uPush.vertexBase
#else
layout(location = 1) uniform vec4 uLightObject; // object space: (position, 1) or (towards light, 0)
layout(location = 3) uniform uint uFlags;       // techniques/volume/GpuVolumeFlags.h
layout(location = 4) uniform uint uFaceCount;
layout(location = 5) uniform uint uDraw;        // this caster's command in uCommands
layout(location = 6) uniform uint uVertexCount; // n: the w = 0 copies' offset
layout(location = 7) uniform uint uFaceBase;    // this mesh's first face in uFaces
layout(location = 8) uniform uint uVertexBase;  // this mesh's first doubled entry where the VS fetches
#endif

layout(std430, binding = 0) buffer Count {
    uint uTriangles;
};
layout(std430, binding = 1) readonly buffer Faces {
    Face uFaces[];
};
layout(std430, binding = 2) writeonly buffer Vertices {
    uint uVertices[]; // per vertex drawn, its doubled entry
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
    return backFacing(uFaces[uFaceBase + f].normal.xyz, uFaces[uFaceBase + f].first.xyz, uLightObject);
}

void main() {
    const uint f = gl_GlobalInvocationID.x;
    if (f >= uFaceCount) return;
    const bool isBack = back(f);
    const uvec3 v = uFaces[uFaceBase + f].vertices.xyz + uVertexBase;
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
    const uint n = uVertexCount;
    if (cap) {
        const uint offset = isBack ? n : 0u;
        uVertices[at++] = v.x + offset;
        uVertices[at++] = v.y + offset;
        uVertices[at++] = v.z + offset;
    }
    for (uint k = 0u; k < 3u; ++k) {
        if ((silhouette & (1u << k)) == 0u) continue;
        const uint a = v[k], b = v[(k + 1u) % 3u];
        // ShadowVolumeMesh's pushSide: (a, b, b'), (a, b', a'), or (a, b, the mesh's first w = 0 entry).
        uVertices[at++] = a;
        uVertices[at++] = b;
        if ((uFlags & SV_DIRECTIONAL) != 0u) {
            uVertices[at++] = uVertexBase + n;
            continue;
        }
        uVertices[at++] = b + n;
        uVertices[at++] = a;
        uVertices[at++] = b + n;
        uVertices[at++] = a + n;
    }
}
