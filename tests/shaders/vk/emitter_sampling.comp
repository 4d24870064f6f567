// Test fixture (EmitterSamplingVkTest): shaders/raytraced/emitter.glsl's emitter samples, read back to be
// compared with reference/LightSampler on the CPU. Compiled from the source tree's root, so that it
// includes the shader the technique compiles, not a copy. SB_EMITTERS comes from addEmitterDefines
// (techniques/raytraced/LightEmitter.h) for the test's scene; the lights' positions and directions from
// a buffer, as the frame block carries them.
//   uPush.mode 0: invocation i samples case i at the case's u (one result);
//   uPush.mode 1: invocation i draws the stratified sequence of the case's pixel and uPush.frame,
//                 uPush.side^2 samples, into results i * side^2 + k.
#include "shaders/raytraced/emitter.glsl"

layout(local_size_x = 64) in;

struct Case {
    vec4 originLight; // xyz: ray origin; w: light index
    vec2 u;           // mode 0: the sample's u
    uvec2 pixel;      // mode 1: the pixel whose stream is drawn
};
struct Result {
    vec4 directionDistance; // the sample's direction and distance
    vec4 uValid;            // xy: the u sampled; z: 1 valid, 0 not
};

layout(std430, set = 0, binding = 0) readonly buffer Cases { Case cases[]; };
layout(std430, set = 0, binding = 1) readonly buffer Lights {
    vec4 lightPos[4];
    vec4 lightDir[4];
};
layout(std430, set = 0, binding = 2) writeonly buffer Results { Result results[]; };
layout(push_constant) uniform Push {
    uint mode;
    uint count; // cases
    int side;
    uint frame;
} uPush;

Result sampleAt(Case c, vec2 u) {
    int light = int(c.originLight.w);
    EmitterSample s = emitterSample(lightEmitter(light), lightPos[light].xyz, lightDir[light].xyz,
                                    c.originLight.xyz, u);
    return Result(vec4(s.direction, s.distance), vec4(u, s.valid ? 1.0 : 0.0, 0.0));
}

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uPush.count) return;
    Case c = cases[i];
    if (uPush.mode == 0u) {
        results[i] = sampleAt(c, c.u);
        return;
    }
    uint state = emitterSeed(c.pixel, uPush.frame);
    int n = uPush.side * uPush.side;
    for (int k = 0; k < n; ++k) results[i * uint(n) + uint(k)] = sampleAt(c, emitterStratum(k, uPush.side, state));
}
