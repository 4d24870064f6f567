// One light's visibility through the ramp (bench/lib/viewer/VisibilityView.h). texelFetch, not texture():
// the target's sampler state stays untouched. Window and target are both bottom-up, as the colour
// view's blit maps them.
#include "viewer/ramp.glsl"
layout(binding = 0) uniform sampler2D uVisibility;
uniform int uLight;
uniform vec2 uWindowSize;
out vec4 oColor;
void main() {
    ivec2 size = textureSize(uVisibility, 0);
    ivec2 texel = clamp(ivec2(gl_FragCoord.xy * vec2(size) / uWindowSize), ivec2(0), size - 1);
    oColor = vec4(sbVisibilityRamp(texelFetch(uVisibility, texel, 0)[uLight]), 1.0);
}
