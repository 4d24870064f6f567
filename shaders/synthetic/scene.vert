// `synthetic`: the scene's triangles with a minimal vertex stage plus uVertexIterations steps of
// arithmetic per vertex (the vertex-bound calibration workload when raised).
#include "common/alu_loop.glsl"
#include "common/frame.glsl"
// On Vulkan the steps are a push constant, in both submission modes: included before
// common/instance.glsl, whose inclusion of it is inside a branch instanced mode does not take.
#ifdef VULKAN
#include "common/push.glsl"
#define uVertexIterations uPush.ints.x
#else
layout(location = 9) uniform int uVertexIterations;
#endif
#include "common/instance.glsl"
out vec4 vColor;

void main() {
    vec4 world = instanceModel() * vec4(aPosition, 1.0);
    // Scaled to nothing but kept: the loop must reach an output to be compiled in.
    float acc = aluLoop(aPosition.xy, uVertexIterations) * 1e-30;
    vColor = vec4(instanceColorId().rgb + acc, 1.0);
    gl_Position = uViewProj * world;
}
