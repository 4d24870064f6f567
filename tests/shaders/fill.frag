// Test fixture: writes testColor() to colour and VIS_VALUE to every visibility channel.
#include "common/test_nested.glsl"
#ifndef VIS_VALUE
#define VIS_VALUE 1.0
#endif
layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oVis;
uniform float uScale;
void main() {
    oColor = testColor() * uScale;
    oVis = vec4(VIS_VALUE);
}
