// `occluder` fragment stage (Appendix B): per light, the product over the mesh's shadow planes of the
// occluder texture at the clamped coordinates (saturate, as the appendix does instead of CLAMP wrap),
// used only where s_I > 0: a plane on the far side of the light casts no (false) shadow. Solid planes
// (the thesis's teapot handle) fetch nothing: inside [0, 1]^2 is shadow.
#include "common/frame.glsl"
#include "common/lighting.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vColorId;
in vec4 vOccluder[LIGHT_COUNT * PLANE_COUNT];
flat in vec4 vLayer[(PLANE_COUNT + 3) / 4];
layout(binding = 0) uniform sampler2DArray uOccluders;
layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oVisibility;

float planeVisibility(vec4 c, float layer) {
    if (c.w == 0.0 || c.z <= 0.0) return 1.0; // unused slot, or the plane is not towards the light
    if (layer < 0.0) return all(greaterThanEqual(c.xy, vec2(0.0))) && all(lessThanEqual(c.xy, vec2(1.0))) ? 0.0 : 1.0;
    return texture(uOccluders, vec3(clamp(c.xy, 0.0, 1.0), layer)).r;
}

void main() {
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing) n = -n;
    vec3 light = uAmbient.rgb;
    vec4 visibility = vec4(1.0);
    for (int i = 0; i < LIGHT_COUNT; ++i) {
        float v = 1.0;
        for (int j = 0; j < PLANE_COUNT; ++j) v *= planeVisibility(vOccluder[i * PLANE_COUNT + j], vLayer[j / 4][j % 4]);
        visibility[i] = v;
        light += v * lightTerm(i, vWorldPos, n);
    }
    oColor = vec4(vColorId.rgb * light, 1.0);
    oVisibility = visibility;
}
