// Test fixture: writes a quiet NaN (bit pattern, not 0/0, which GLSL leaves undefined) to visibility
// channel 0, +Inf to channel 1, 0.25 and 0.75 to channels 2 and 3.
layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oVis;
void main() {
    oColor = vec4(0.0, 1.0, 0.0, 1.0);
    oVis = vec4(uintBitsToFloat(0x7fc00000u), uintBitsToFloat(0x7f800000u), 0.25, 0.75);
}
