// `projective` lighting pass for the receivers (the instances that cast no shadow): each light's
// projective texture projected onto them (common/scene.vert with SHADOW_MAP computes
// vShadowCoord[i] = bias * projector_i * world). No depth comparison: whatever the projector saw of
// the casters darkens every receiver it projects onto (the technique's header says which problems
// remain). q <= 0: the point is behind a perspective projector, where the projection would mirror the
// silhouette onto it; it is lit. Outside the frustum the sampler's white border says lit.
#include "common/frame.glsl"
#include "common/lighting.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vColorId;
in vec4 vShadowCoord[LIGHT_COUNT];
layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oVisibility;

#ifdef VULKAN
// Set 1 (techniques/projective/ProjectiveVulkan.h): binding 0 the texture matrices (common/scene.vert's
// ShadowMapBlock), binding 1 the textures.
layout(set = 1, binding = 1) uniform sampler2DArray uProjective;
#else
layout(binding = 0) uniform sampler2DArray uProjective;
#endif

float visibility(int layer, vec4 coord) {
    if (coord.q <= 0.0) return 1.0;
    return texture(uProjective, vec3(coord.st / coord.q, float(layer))).r;
}

void main() {
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing) n = -n;
    vec3 light = ambientLight();
    vec4 vis = vec4(1.0);
    for (int i = 0; i < LIGHT_COUNT; ++i) {
        vis[i] = shadowApplies(i, vColorId) ? visibility(i, vShadowCoord[i]) : 1.0;
        light += vis[i] * lightTerm(i, vWorldPos, n);
    }
    oColor = vec4(vColorId.rgb * light, 1.0);
    oVisibility = vis;
}
