// `blob`: the ellipse's soft profile removes its light from the ground. Blending (BlobTechnique):
// colour = dst - src (reverse subtract), visibility = dst * src.
#include "common/frame.glsl"
// The blob darkens the ground at this fragment (lightTermAt): no surface of its own.
#define SB_NO_LIGHT_TERMS
#include "common/lighting.glsl"

in vec2 vCorner;
in vec3 vWorld;
flat in vec3 vParams;
#ifdef VULKAN
// The push constants (common/push.glsl, techniques/blob/BlobVulkan.h): the ground's plane in vec, its
// colour in colorId.
#include "common/push.glsl"
#define uPlane uPush.vec
#define uAlbedo uPush.colorId.rgb
#else
layout(location = 12) uniform vec4 uPlane;  // the ground: (n, d)
layout(location = 14) uniform vec3 uAlbedo; // the ground's colour
#endif
layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oVisibility;

void main() {
    float softness = vParams.z;
    float r = length(vCorner);
    // softness 0 is a hard ellipse (smoothstep's edges would coincide: step instead).
    float profile = softness > 0.0 ? 1.0 - smoothstep(1.0 - softness, 1.0, r) : (r <= 1.0 ? 1.0 : 0.0);
    float alpha = vParams.x * profile;
    int light = int(vParams.y);
    oColor = vec4(alpha * uAlbedo * lightTermAt(light, vWorld, uPlane.xyz), 0.0);
    vec4 v = vec4(1.0);
    v[light] = 1.0 - alpha;
    oVisibility = v;
}
