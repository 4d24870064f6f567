// The exponential variance shadow map lookup (Lauritzen and McCool 2008, Layered Variance Shadow Maps, GI,
// the section on the exponential warp; Chebyshev's bound as in Lauritzen 2007, GPU Gems 3 ch. 8, section
// 8.4.2), apart from the texture fetch so that tests can evaluate it on moments they computed by hand
// (tests/MsmEvsmVkTest.cpp). Chebyshev's bound and the light-bleeding reduction are vsm's (shadowmap/vsm.glsl).
//
// Depth d in [0, 1] is warped before its moments are taken: the positive warp exp(c+ d) and the negative
// warp -exp(-c- d), both increasing in d, so "in front of t" keeps its meaning and Chebyshev's bound holds
// in the warped space. The positive warp stretches the depths behind an occluder far apart from its own,
// which is where VSM's bound leaks light (a receiver close behind the farther of two occluders); the
// negative warp does the same for the nearer depths, and the lit fraction is the smaller of the two bounds
// (both are upper bounds of the same fraction).
#include "shadowmap/vsm.glsl"

// The two warps of depth d: (exp(c+ d), -exp(-c- d)).
vec2 evsmWarp(float d, vec2 exponents) { return vec2(exp(exponents.x * d), -exp(-exponents.y * d)); }

// The moments a depth pass stores for depth d: (w+, w+^2, w-, w-^2) of the warps, the second moments biased
// as VSM's by 0.25 |grad w|^2 of the warped depth (`gradient`: d's screen derivatives (dFdx, dFdy)), so a
// sloped surface does not shadow itself after filtering.
vec4 evsmMoments(float d, vec2 gradient, vec2 exponents) {
    vec2 w = evsmWarp(d, exponents);
    // d/dd of each warp: c+ w+ and -c- w- (both positive).
    vec2 slope = vec2(exponents.x * w.x, -exponents.y * w.y);
    float g = dot(gradient, gradient);
    return vec4(w.x, w.x * w.x + 0.25 * slope.x * slope.x * g, w.y, w.y * w.y + 0.25 * slope.y * slope.y * g);
}

// The lit fraction for a receiver at depth t from the filtered warped moments: Chebyshev's bound in each
// warped space (the negative one only when `negative`), the smaller of the two, with the light-bleeding
// reduction of vsm. The minimum variance is given on linear depth (as vsm's `min_variance`) and scaled into
// each warped space by the warp's slope at t, squared.
float evsmVisibility(vec4 moments, float t, vec2 exponents, bool negative, float minVariance, float bleed) {
    vec2 w = evsmWarp(t, exponents);
    vec2 slope = vec2(exponents.x * w.x, -exponents.y * w.y);
    float p = chebyshevUpperBound(moments.xy, w.x, minVariance * slope.x * slope.x);
    if (negative) p = min(p, chebyshevUpperBound(moments.zw, w.y, minVariance * slope.y * slope.y));
    return reduceLightBleeding(p, bleed);
}
