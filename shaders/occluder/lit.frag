// `occluder` fragment stage (Appendix B): per light, the product over the mesh's shadow planes of the
// occluder texture at the clamped coordinates (saturate, as the appendix does instead of CLAMP wrap),
// used only where s_I > 0: a plane on the far side of the light casts no (false) shadow. Solid planes
// (the thesis's teapot handle) fetch nothing: inside [0, 1]^2 is shadow.
#include "common/frame.glsl"
#include "common/lighting.glsl"

#ifdef VULKAN
// Set 1 (techniques/occluder/OccluderVulkan.h): the same bindings as GL's, in the technique's set.
#define OCCLUDER_SET set = 1,
#else
#define OCCLUDER_SET
#endif

in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vColorId;
in vec4 vOccluder[LIGHT_COUNT * PLANE_COUNT];
flat in vec4 vLayer[(PLANE_COUNT + 3) / 4];
layout(OCCLUDER_SET binding = 0) uniform sampler2DArray uOccluders;


layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oVisibility;

float planeVisibility(vec4 c, float layer) {
    // Unused slot or a section that does not receive the plane (w interpolates 0 and 1: a triangle
    // across sections takes its nearer vertices' side), or the plane is not towards the light.
    if (c.w < 0.5 || c.z <= 0.0) return 1.0;
    if (layer < 0.0) return all(greaterThanEqual(c.xy, vec2(0.0))) && all(lessThanEqual(c.xy, vec2(1.0))) ? 0.0 : 1.0;
    return texture(uOccluders, vec3(clamp(c.xy, 0.0, 1.0), layer)).r;
}

#ifdef RECEIVE_OTHERS
// receivers=all: every instance's planes in world space (same layout as OccluderPlane in scene.vert),
// and per receiver instance a (first, count) range of candidate casters, each a (first world plane,
// plane count) pair stored after the INSTANCE_COUNT ranges.
struct WorldPlane {
    vec4 origin; // w: texture layer, < 0 solid
    vec4 normal;
    vec4 right;  // right / width (world units)
    vec4 up;     // up / height
};
layout(std430, OCCLUDER_SET binding = 5) readonly buffer OccluderWorldPlanes {
    WorldPlane uWorldPlanes[];
};
layout(std430, OCCLUDER_SET binding = 6) readonly buffer OccluderCandidates {
    uvec2 uCandidates[];
};

// Equations 6 and 8 per fragment, in world space, for a plane of another instance.
float worldPlaneVisibility(WorldPlane p, vec3 pos, vec3 towardLight) {
    float cosine = dot(p.normal.xyz, towardLight);
    cosine = abs(cosine) < 1e-6 ? (cosine < 0.0 ? -1e-6 : 1e-6) : cosine;
    float s = dot(p.normal.xyz, p.origin.xyz - pos) / cosine;
    if (s <= 0.0) return 1.0;
    vec3 d = pos + s * towardLight - p.origin.xyz;
    vec2 uv = vec2(dot(p.right.xyz, d), dot(p.up.xyz, d));
    // Outside the rectangle no fetch: a baked texture's border is clear there anyway, and another
    // instance's loaded image does not stretch its border across the scene.
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 1.0;
    return planeVisibility(vec4(uv, s, 1.0), p.origin.w);
}

float othersVisibility(int light) {
    uvec2 range = uCandidates[int(abs(vColorId.w)) - 1];
    vec3 towardLight = toLight(light, vWorldPos);
    float v = 1.0;
    for (uint k = 0u; k < range.y && v > 0.0; ++k) {
        uvec2 planes = uCandidates[uint(INSTANCE_COUNT) + range.x + k];
        for (uint j = 0u; j < planes.y; ++j) v *= worldPlaneVisibility(uWorldPlanes[planes.x + j], vWorldPos, towardLight);
    }
    return v;
}
#endif

void main() {
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing) n = -n;
    vec3 light = ambientLight();
    vec4 visibility = vec4(1.0);
    for (int i = 0; i < LIGHT_COUNT; ++i) {
        float v = 1.0;
        if (shadowApplies(i, vColorId)) {
            for (int j = 0; j < PLANE_COUNT; ++j) v *= planeVisibility(vOccluder[i * PLANE_COUNT + j], vLayer[j / 4][j % 4]);
#ifdef RECEIVE_OTHERS
            v *= othersVisibility(i);
#endif
        }
        visibility[i] = v;
        light += v * lightTerm(i, vWorldPos, n);
    }
    oColor = vec4(vColorId.rgb * light, 1.0);
    oVisibility = visibility;
}
