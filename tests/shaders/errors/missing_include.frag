// Test fixture: line 3 includes a file that does not exist.
layout(location = 0) out vec4 oColor;
#include "common/does_not_exist.glsl"
void main() {
    oColor = vec4(1.0);
}
