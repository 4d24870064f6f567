// Test fixture: the error is in the included file (common/test_broken.glsl line 4).
#include "common/test_broken.glsl"
layout(location = 0) out vec4 oColor;
void main() {
    oColor = vec4(brokenHelper());
}
