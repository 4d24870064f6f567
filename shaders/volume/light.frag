// `volume` light pass for one light (GPU Gems ch. 9, Listing 9-1): drawn where the stencil count is 0
// (outside every shadow volume) with depth EQUAL and additive blending (ONE, ONE), so it adds this
// light's diffuse term to the ambient pass and 1 to this light's visibility channel.
#include "common/frame.glsl"
#include "common/lighting.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vColorId;
layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oVisibility;
#ifdef VULKAN
// The light index in the push constants (techniques/volume/VolumeVulkan.h).
#include "common/push.glsl"
#define uLightIndex uPush.ints.x
#else
layout(location = 12) uniform int uLightIndex;
#endif

void main() {
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing) n = -n;
    oColor = vec4(vColorId.rgb * lightTerm(uLightIndex, vWorldPos, n), 0.0);
    oVisibility = vec4(equal(ivec4(0, 1, 2, 3), ivec4(uLightIndex)));
}
