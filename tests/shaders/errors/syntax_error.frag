// Test fixture: ProgramCacheGLTest expects a compile error at line 7 of this file.
#include "common/test_colors.glsl"
layout(location = 0) out vec4 oColor;
void main() {
    vec4 c = testColor();
    // the next line lacks a semicolon before "oColor"
    float broken = 1.0 oColor = c;
}
