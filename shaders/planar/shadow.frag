// `planar` shadow polygons: remove light LIGHT (uniform) from the receiver where a flattened occluder
// lands. Blending (PlanarTechnique): colour = dst - src (reverse subtract), visibility = dst * src.
#include "common/frame.glsl"
// The flattened occluder darkens the receiver at this fragment (lightTermAt): no surface of its own.
#define SB_NO_LIGHT_TERMS
#include "common/lighting.glsl"

in vec4 vFlat;
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
layout(location = 12) uniform vec4 uPlane;
layout(location = 14) uniform vec4 uAlbedoLight; // rgb: the receiver's albedo; w: light index
layout(location = 15) uniform float uDarkness;   // 1: the light is fully removed
#endif
layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oVisibility;

void main() {
    int light = int(uAlbedoLight.w);
    vec3 p = vFlat.xyz / vFlat.w;
    oColor = vec4(uDarkness * uAlbedoLight.rgb * lightTermAt(light, p, uPlane.xyz), 0.0);
    vec4 v = vec4(1.0);
    v[light] = 1.0 - uDarkness;
    oVisibility = v;
}
