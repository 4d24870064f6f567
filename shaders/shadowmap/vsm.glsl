// The variance shadow map lookup (Donnelly and Lauritzen 2006, Variance Shadow Maps, section 3, equation 5;
// Lauritzen 2007, GPU Gems 3 ch. 8, Listings 8-2 and 8-4), apart from the texture fetch so that tests can
// evaluate it on moments they computed by hand (tests/MomentShadowGLTest.cpp).

// Chebyshev's one-tailed bound on the fraction of the filter region at depth >= t (the lit fraction), from
// the moments M1 = E[d], M2 = E[d^2]: 1 for t <= M1, else sigma^2 / (sigma^2 + (t - M1)^2) with
// sigma^2 = max(M2 - M1^2, minVariance) (the clamp of section 8.4.2: rounding can make M2 - M1^2 negative).
float chebyshevUpperBound(vec2 moments, float t, float minVariance) {
    if (t <= moments.x) return 1.0;
    float variance = max(moments.y - moments.x * moments.x, minVariance);
    float d = t - moments.x;
    return variance / (variance + d * d);
}

float linstep(float lo, float hi, float v) { return clamp((v - lo) / (hi - lo), 0.0, 1.0); }

// Light-bleeding reduction (section 8.4.3): the bound's [0, amount] tail, where a second occluder behind
// the first leaves a halo, goes to 0 and (amount, 1] is rescaled to (0, 1]. amount < 1.
float reduceLightBleeding(float pMax, float amount) { return linstep(amount, 1.0, pMax); }
