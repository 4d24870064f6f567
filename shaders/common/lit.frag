// Lit, unshadowed: the whole of `none` (the baseline of every overhead ratio), and the lit pass that
// `planar`, `blob` and `projective` draw before darkening. Visibility is 1 for every light.
#include "common/frame.glsl"
#include "common/lighting.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vColorId;
layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oVisibility;

void main() {
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing) n = -n;
    vec3 light = ambientLight();
    for (int i = 0; i < LIGHT_COUNT; ++i) light += lightTerm(i, vWorldPos, n);
    oColor = vec4(vColorId.rgb * light, 1.0);
    oVisibility = vec4(1.0);
}
