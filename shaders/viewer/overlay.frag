// Text: texelFetch at the pixel's texel (a glyph quad is a whole number of pixels per texel, so every
// pixel centre falls inside exactly one texel), ink opaque white, blank discarded.
#include "viewer/ramp.glsl"
layout(binding = 0) uniform sampler2D uAtlas;
uniform float uBoxOpacity;
in vec2 vUv;
flat in int vMode;
out vec4 oColor;
void main() {
    if (vMode == 0) {
        oColor = vec4(0.0, 0.0, 0.0, uBoxOpacity);
    } else if (vMode == 1) {
        if (texelFetch(uAtlas, ivec2(floor(vUv)), 0).r < 0.5) discard;
        oColor = vec4(1.0);
    } else {
        oColor = vec4(sbVisibilityRamp(clamp(vUv.x, 0.0, 1.0)), 1.0);
    }
}
