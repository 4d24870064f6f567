// `synthetic`: the full-screen pass, uFragmentIterations steps of arithmetic per pixel (the fill-bound
// calibration workload). Drawn with common/fullscreen.vert (a full-screen triangle from gl_VertexID).
#include "common/alu_loop.glsl"
#ifdef VULKAN
// Push constants: x the steps, vec.x the target's height (GL's window coordinates count rows from the
// bottom, Vulkan's from the top: the same pixel gets the same value on both APIs).
#include "common/push.glsl"
#define uFragmentIterations uPush.ints.x
vec2 pixelCoord() { return vec2(gl_FragCoord.x, uPush.vec.x - gl_FragCoord.y); }
#else
layout(location = 0) uniform int uFragmentIterations;
vec2 pixelCoord() { return gl_FragCoord.xy; }
#endif
layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oVisibility;

void main() {
    float acc = aluLoop(pixelCoord() * 0.001, uFragmentIterations);
    oColor = vec4(fract(acc), 0.5, 0.5, 1.0);
    oVisibility = vec4(1.0);
}
