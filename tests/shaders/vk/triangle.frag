// Test fixture (VulkanTargetsVkTest): the push constant's colour to attachment 0, VIS_VALUE to every
// visibility channel (attachment 1).
#ifndef VIS_VALUE
#define VIS_VALUE 0.5
#endif
layout(push_constant) uniform Push {
    vec4 colour;
} uPush;
layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oVis;
void main() {
    oColor = uPush.colour;
    oVis = vec4(VIS_VALUE);
}
