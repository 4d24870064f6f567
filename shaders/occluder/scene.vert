// `occluder` (Coleman, "Fast Self-Shadowing Using Occluder Textures", section 4 and Appendix A): the
// vertex stage projects the vertex onto each shadow plane of its mesh along the light (equations 6 and
// 8) and passes (u, v, s_I) per light and plane; the fragment stage (occluder/lit.frag) looks up the
// occluder textures. For a directional light u, v and s_I are affine in the vertex position, so the
// interpolated values are exact; for point lights they are per-vertex approximations.
//
// Defines: LIGHT_COUNT, PLANE_COUNT (the most planes any mesh uses, >= 1), LIGHT_PER_INSTANCE (the
// thesis's proposed optimisation: the light in model space computed once per instance on the CPU;
// without it every vertex transforms the light into model space, as the thesis's shader does),
// TEXTURE_MATRIX (the thesis's future work, "texture matrices to perform the projection": for a
// directional light (u, v, s_I) are affine in the vertex, so the CPU folds equations 6 and 8 into one
// 3x4 matrix per instance, light and plane and the vertex stage does three dot products per plane),
// RECEIVER_SECTIONS (some plane names the mesh parts that receive it, the thesis's receiver sections:
// the vertex looks up the planes it receives in its mesh's hash table, techniques/occluder/
// ReceiverSections.h, and marks the others unused in w; u, v and s_I are still computed, so a triangle
// interpolates them exactly whatever its vertices' sections).
#include "common/frame.glsl"
#include "common/lighting.glsl"
#include "common/instance.glsl"

#ifdef VULKAN
// Set 1 (techniques/occluder/OccluderVulkan.h): the same bindings as GL's, in the technique's set.
#define OCCLUDER_SET set = 1,
#else
#define OCCLUDER_SET
#endif

struct OccluderPlane {
    vec4 origin; // xyz: texture corner (object space); w: texture layer, < 0 for a solid occluder
    vec4 normal; // xyz: unit normal
    vec4 right;  // xyz: right / width
    vec4 up;     // xyz: up / height
};
layout(std430, OCCLUDER_SET binding = 2) readonly buffer OccluderPlanes {
    OccluderPlane uPlanes[];
};
// Per instance (object id - 1): x = first plane, y = plane count, z = first slot of the mesh's receiver
// section table, w = its slot count (0: every vertex receives every plane); then, with LIGHT_PER_INSTANCE, the
// lights in the instance's model space ((direction towards the light, 0) or (position, 1)).
struct OccluderInstance {
    uvec4 planes;
    vec4 light[LIGHT_COUNT];
};
layout(std430, OCCLUDER_SET binding = 3) readonly buffer OccluderInstances {
    OccluderInstance uInstances[];
};

#ifdef TEXTURE_MATRIX
// Per instance, light and plane: rows u, v, s of the affine map, at
// ((instance * LIGHT_COUNT + light) * PLANE_COUNT + plane) * 3.
layout(std430, OCCLUDER_SET binding = 4) readonly buffer OccluderMatrices {
    vec4 uMatrices[];
};
#endif

#ifdef RECEIVER_SECTIONS
// Slots (x, y, z bits of a vertex position, mask of the planes it receives; 0xFFFFFFFF = free).
layout(std430, OCCLUDER_SET binding = 7) readonly buffer OccluderSections {
    uvec4 uSections[];
};

// ReceiverSections::hash.
uint sectionHash(uvec3 b) {
    uint h = b.x;
    h = h * 0x9E3779B1u ^ b.y;
    h = h * 0x85EBCA77u ^ b.z;
    h ^= h >> 16;
    h *= 0x7FEB352Du;
    h ^= h >> 15;
    h *= 0x846CA68Bu;
    h ^= h >> 16;
    return h;
}

// ReceiverSections::lookup: the planes this vertex receives (all when the mesh has no table).
uint receivedPlanes(uvec2 range) {
    if (range.y == 0u) return 0xFFFFu;
    uvec3 key = floatBitsToUint(aPosition);
    uint slot = sectionHash(key) & (range.y - 1u);
    for (uint n = 0u; n < range.y; ++n, slot = (slot + 1u) & (range.y - 1u)) {
        uvec4 e = uSections[range.x + slot];
        if (e.w == 0xFFFFFFFFu) break;
        if (e.xyz == key) return e.w;
    }
    return 0xFFFFu;
}
#else
uint receivedPlanes(uvec2 range) { return 0xFFFFu; }
#endif

out vec3 vWorldPos;
out vec3 vNormal;
out vec4 vColorId;
out vec4 vOccluder[LIGHT_COUNT * PLANE_COUNT]; // (u, v, s_I, 1 = plane used) per light and plane
flat out vec4 vLayer[(PLANE_COUNT + 3) / 4];   // texture layer per plane, < 0: solid

// The light in model space, as the thesis's vertex shader computes it for every vertex: instances have
// uniform scale, so the inverse of mat3(model) is its transpose over the squared scale.
vec4 lightInModelSpace(int i, mat4 model) {
    mat3 m = mat3(model);
    float scale2 = dot(m[0], m[0]);
    if (uLightPos[i].w == 0.0) return vec4(normalize(transpose(m) * -uLightDir[i].xyz), 0.0);
    return vec4(transpose(m) * (uLightPos[i].xyz - model[3].xyz) / scale2, 1.0);
}

void main() {
    mat4 model = instanceModel();
    vec4 world = model * vec4(aPosition, 1.0);
    vWorldPos = world.xyz;
    vNormal = mat3(model) * aNormal;
    vColorId = instanceColorId();
    gl_Position = uViewProj * world;
#ifdef SB_VERTEX_LIGHTING
    writeVertexLighting(world.xyz, normalize(vNormal)); // common/lighting.glsl, `--lighting vertex`
#endif

    OccluderInstance inst = uInstances[int(abs(vColorId.w)) - 1];
    int first = int(inst.planes.x), count = min(int(inst.planes.y), PLANE_COUNT);
    uint received = receivedPlanes(inst.planes.zw);
    for (int j = 0; j < PLANE_COUNT; ++j) vLayer[j / 4][j % 4] = j < count ? uPlanes[first + j].origin.w : 0.0;
#ifdef TEXTURE_MATRIX
    int instanceIndex = int(abs(vColorId.w)) - 1;
    vec4 p1 = vec4(aPosition, 1.0);
    for (int i = 0; i < LIGHT_COUNT; ++i)
        for (int j = 0; j < PLANE_COUNT; ++j) {
            if (!shadowApplies(i, vColorId)) { // lit: the fragment stage reads none of it
                vOccluder[i * PLANE_COUNT + j] = vec4(0.0);
                continue;
            }
            int m = ((instanceIndex * LIGHT_COUNT + i) * PLANE_COUNT + j) * 3;
            float use = float((received >> uint(j)) & 1u);
            vOccluder[i * PLANE_COUNT + j] = j < count ? vec4(dot(uMatrices[m], p1), dot(uMatrices[m + 1], p1),
                                                              dot(uMatrices[m + 2], p1), use)
                                                       : vec4(0.0);
        }
#else
    for (int i = 0; i < LIGHT_COUNT; ++i) {
        if (!shadowApplies(i, vColorId)) { // lit: the fragment stage reads none of it
            for (int j = 0; j < PLANE_COUNT; ++j) vOccluder[i * PLANE_COUNT + j] = vec4(0.0);
            continue;
        }
#ifdef LIGHT_PER_INSTANCE
        vec4 l = inst.light[i];
#else
        vec4 l = lightInModelSpace(i, model);
#endif
        // Unit vector towards the light from this vertex (equation 2's L).
        vec3 towardLight = l.w == 0.0 ? l.xyz : normalize(l.xyz - aPosition);
        for (int j = 0; j < PLANE_COUNT; ++j) {
            if (j >= count) {
                vOccluder[i * PLANE_COUNT + j] = vec4(0.0);
                continue;
            }
            OccluderPlane p = uPlanes[first + j];
            // Equation 6, its denominator held away from 0 with its sign (ShadowPlane::kMinCosine):
            // a light parallel to the plane gives a huge but finite s_I, never 0 / 0.
            float cosine = dot(p.normal.xyz, towardLight);
            cosine = abs(cosine) < 1e-6 ? (cosine < 0.0 ? -1e-6 : 1e-6) : cosine;
            float s = dot(p.normal.xyz, p.origin.xyz - aPosition) / cosine;
            vec3 d = aPosition + s * towardLight - p.origin.xyz; // p(s_I) - o
            // Equation 8 (from the texture's corner, as Appendix A computes it).
            // w: 1 where this vertex's section receives the plane (a triangle inside one section has
            // the same w at its three vertices).
            vOccluder[i * PLANE_COUNT + j] =
                vec4(dot(p.right.xyz, d), dot(p.up.xyz, d), s, float((received >> uint(j)) & 1u));
        }
    }
#endif
}
