// A fragment-bound loop whose cost is the same for every pixel, so frame cost is proportional to the
// pixel count. The result feeds the output so the loop cannot be optimised away.
#include "common/alu_loop.glsl"
#ifdef VULKAN
#include "common/push.glsl"
#define uIterations uPush.ints.x
#else
layout(location = 0) uniform int uIterations;
#endif
layout(location = 0) out vec4 oColor;

void main() {
    float acc = aluLoop(gl_FragCoord.xy * 0.001, uIterations);
    oColor = vec4(fract(acc), 0.0, 0.0, 1.0);
}
