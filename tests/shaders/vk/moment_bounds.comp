// Test fixture (MsmEvsmVkTest): the lookups of shaders/shadowmap/msm.glsl, evsm.glsl and vsm.glsl on moments
// the test computed by hand, read back to be compared with closed-form answers. Compiled from a root that
// links shaders/shadowmap as shadowmap/ (the includes are written from shaders/, as the techniques'), so it
// includes the shaders the techniques compile, not copies.
//   mode 0: hamburger4(moments, t, bias)                                   (msm, float map)
//   mode 1: the same after msmQuantize, rounding to 16-bit unorm and msmDequantize (msm, unorm16 map)
//   mode 2: evsmVisibility(moments, t, exponents, false, minVariance, bleed) (evsm, components=2)
//   mode 3: evsmVisibility(moments, t, exponents, true, minVariance, bleed)  (evsm, components=4)
//   mode 4: msmQuantize(msmMoments(t))    (the unorm16 map's value of depth t)
//   mode 5: evsmMoments(t, (0, 0), exponents)
//   mode 6: reduceLightBleeding(chebyshevUpperBound(moments.xy, t, minVariance), bleed)  (vsm)
#include "shadowmap/evsm.glsl"
#include "shadowmap/msm.glsl"
#include "shadowmap/vsm.glsl"

layout(local_size_x = 64) in;

struct Case {
    vec4 moments;   // the filtered moments (raw: E[d^k], or the warps' moments)
    vec4 params;    // t, bias (msm) or minVariance (evsm, vsm), bleed reduction, mode
    vec4 exponents; // xy: c+, c- (evsm)
};

layout(std430, set = 0, binding = 0) readonly buffer Cases { Case cases[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Results { vec4 results[]; };
layout(push_constant) uniform Push { uint count; } uPush;

vec4 evaluate(Case c) {
    float t = c.params.x, bias = c.params.y, bleed = c.params.z;
    int mode = int(c.params.w);
    if (mode == 0) return vec4(hamburger4(c.moments, t, bias));
    if (mode == 1) {
        vec4 q = round(clamp(msmQuantize(c.moments), 0.0, 1.0) * 65535.0) / 65535.0;
        return vec4(hamburger4(msmDequantize(q), t, bias));
    }
    if (mode == 2) return vec4(evsmVisibility(c.moments, t, c.exponents.xy, false, bias, bleed));
    if (mode == 3) return vec4(evsmVisibility(c.moments, t, c.exponents.xy, true, bias, bleed));
    if (mode == 4) return msmQuantize(msmMoments(t));
    if (mode == 5) return evsmMoments(t, vec2(0.0), c.exponents.xy);
    return vec4(reduceLightBleeding(chebyshevUpperBound(c.moments.xy, t, bias), bleed)); // mode 6
}

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uPush.count) return;
    results[i] = evaluate(cases[i]);
}
