// The exponential shadow map lookup (Annen, Mertens, Seidel, Bekaert, Kautz 2008, Exponential Shadow Maps,
// section 3, equation 5), in log space (Salvi 2008, ShaderX6), apart from the texture fetch so that tests
// can evaluate it on depths and weights they chose by hand (tests/MomentShadowGLTest.cpp).
//
// visibility = clamp(exp(-c t) sum_k w_k exp(c d_k), 0, 1) for four filter taps d_k with weights w_k
// (summing to 1), computed as exp(min(c (m - t) + log(sum_k w_k exp(c (d_k - m))), 0)) with m the largest
// d_k among the taps of non-zero weight: every exp() is at most 1, the sum at least the weight of the tap
// at m (> 0), and a weight-0 tap deeper than m (0 * exp(+large) = NaN) is left out. Finite and in [0, 1]
// at every exponent, where exp(c d) itself overflows a float from c d = 88.7 on.
float exponentialVisibility(vec4 depths, vec4 weights, float t, float c) {
    float m = -3.0e38;
    for (int k = 0; k < 4; ++k)
        if (weights[k] > 0.0) m = max(m, depths[k]);
    float sum = 0.0;
    for (int k = 0; k < 4; ++k)
        if (weights[k] > 0.0) sum += weights[k] * exp(c * (depths[k] - m));
    return exp(min(c * (m - t) + log(sum), 0.0));
}
