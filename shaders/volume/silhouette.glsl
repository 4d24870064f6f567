// The GPU silhouette paths' one definition of a face's classification and of what a face contributes
// (techniques/volume/ShadowVolumeMesh.cpp's buildVolume under the Closed policy, per face):
//  - a light cap triangle when it faces the light (kLightCap), a dark cap triangle at infinity when it
//    does not (kDarkCap);
//  - per directed edge a -> b whose face across faces the light while this one does not, the side
//    through that edge as this back face traverses it: (a, b, b'), (a, b', a') with ' at infinity,
//    or (a, b, L') in the directional form (kDirectional). Each silhouette edge has exactly one back
//    face, so each side is built once, as on the CPU.
// The flags are techniques/volume/GpuVolumeFlags.h's.
#define SV_LIGHT_CAP 1u
#define SV_DARK_CAP 2u
#define SV_SIDES 4u
#define SV_DIRECTIONAL 8u

// Listing 9-5 as ShadowVolumeMesh::classifyFaces computes it (N unnormalised, P0 the face's first
// vertex, L.xyz - P0 L.w), `precise` so that no multiply-add is fused: the CPU's float operations in
// the CPU's order, so both sides classify grazing faces alike and the counts agree exactly.
bool backFacing(vec3 n, vec3 p0, vec4 light) {
    precise vec3 towards = light.xyz - p0 * light.w;
    precise float d = n.x * towards.x + n.y * towards.y + n.z * towards.z;
    return d < 0.0;
}

// silhouette.comp's and silhouette.mesh's face record (techniques/volume/SilhouetteInputs.h, std430).
struct Face {
    uvec4 vertices;   // welded indices, counter-clockwise
    uvec4 neighbours; // the face across (v0, v1), (v1, v2), (v2, v0)
    vec4 normal;      // unnormalised, as ShadowVolumeMesh::faceNormals
    vec4 first;       // the face's first vertex
};

// Triangles a face contributes: its cap (1 or 0) and 2 per side (1 directional).
uint sideTriangles(uint flags) {
    return (flags & SV_DIRECTIONAL) != 0u ? 1u : 2u;
}
