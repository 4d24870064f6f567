// Test fixture (DeviceCountVkTest): every invocation adds its n to one 64-bit count through
// shaders/raytraced/count64.glsl's COUNT64_ADD, the macro the ray-traced lighting pass counts its rays
// with. Invocation i adds n = uPush.base + ((i * 2654435761 + uPush.offset) & uPush.mask) (uint arithmetic,
// mod 2^32), which the test sums on the CPU.
#include "shaders/raytraced/count64.glsl"

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 0) buffer Count {
    uint uLow;
    uint uHigh;
};
layout(push_constant) uniform Push {
    uint invocations;
    uint offset;
    uint mask;
    uint base;
} uPush;

void main() {
    const uint i = gl_GlobalInvocationID.x;
    if (i >= uPush.invocations) return;
    COUNT64_ADD(uLow, uHigh, uPush.base + ((i * 2654435761u + uPush.offset) & uPush.mask));
}
