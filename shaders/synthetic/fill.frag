// `synthetic`: the full-screen pass, uFragmentIterations steps of arithmetic per pixel (the fill-bound
// calibration workload). Drawn with common/fullscreen.vert (a full-screen triangle from gl_VertexID).
#include "common/alu_loop.glsl"
layout(location = 0) uniform int uFragmentIterations;
layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oVisibility;

void main() {
    float acc = aluLoop(gl_FragCoord.xy * 0.001, uFragmentIterations);
    oColor = vec4(fract(acc), 0.5, 0.5, 1.0);
    oVisibility = vec4(1.0);
}
