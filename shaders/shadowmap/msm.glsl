// The moment shadow map lookup (Peters and Klein 2015, Moment Shadow Mapping, I3D): the four power moments
// b = (E[d], E[d^2], E[d^3], E[d^4]) of the filter region's depths, stored either as floats or quantised to
// 16-bit unorm by the paper's optimised affine transform (its section on quantization), and the Hamburger
// four-moment reconstruction of the fraction of the region in front of the receiver (its Hamburger 4MSM
// algorithm with the moment bias alpha). Apart from the texture fetch so that tests can evaluate it
// on moments they computed by hand (tests/MsmEvsmVkTest.cpp).
//
// The quantisation. The raw moments of d in [0, 1] are strongly correlated (d^4 <= d^3 <= d^2 <= d), so
// 16 bits each would lose most of the information in their differences; the paper's transform
// b' = Q b + (0.035955884801, 0, 0, 0) maps every moment vector of a distribution on [0, 1] into [0, 1]^4 and
// spreads them over it. It is linear, so filtering the stored b' is filtering b; msmDequantize() undoes it
// before the reconstruction. Q's rows are the transform's columns (GLSL's mat4() takes columns): b'_i =
// sum_k Q[k][i] b_k, which is what `kMsmQuantize * b` computes.
const mat4 kMsmQuantize = mat4(-2.07224649, 13.7948857237, 0.105877704, 9.7924062118,          //
                               32.23703778, -59.4683975703, -1.9077466311, -33.7652110555,     //
                               -68.571074599, 82.0359750338, 9.3496555107, 47.9456096605,      //
                               39.3703274134, -35.364903257, -6.6543490743, -23.9728048165);
const mat4 kMsmDequantize = mat4(0.2227744146, 0.1549679261, 0.1451988946, 0.163127443,       //
                                 0.0771972861, 0.1394629426, 0.2120202157, 0.2591432266,      //
                                 0.7926986636, 0.7963415838, 0.7258694464, 0.6539092497,      //
                                 0.0319417555, -0.1722823173, -0.2758014811, -0.3376131734);
const vec4 kMsmQuantizeOffset = vec4(0.035955884801, 0.0, 0.0, 0.0);

// The four power moments of one depth.
vec4 msmMoments(float d) {
    float d2 = d * d;
    return vec4(d, d2, d2 * d, d2 * d2);
}

vec4 msmQuantize(vec4 b) { return kMsmQuantize * b + kMsmQuantizeOffset; }
vec4 msmDequantize(vec4 q) { return kMsmDequantize * (q - kMsmQuantizeOffset); }

// The fraction of the filter region in front of a receiver at depth t (the shadow intensity; visibility is
// one minus it), from its moments b (not quantised). Hamburger four-moment reconstruction:
// 1. The moment bias: b is pulled towards the moments (0.5, 0.5, 0.5, 0.5) by `bias` (alpha), which keeps the
//    Hankel matrix B below positive definite after filtering and rounding.
// 2. Solve B c = (1, t, t^2) for B = ((1, b1, b2), (b1, b2, b3), (b2, b3, b4)) (Cholesky: B is symmetric
//    positive definite).
// 3. The roots z2 <= z3 of c3 z^2 + c2 z + c1 = 0 are, with t, the support of the distribution of three
//    points that matches the moments and puts most of its weight at t (the bound's extremal measure).
// 4. Its weight in front of t: 0 when t <= z2; for z2 < t <= z3 the weight of z2,
//    (t z3 - b1 (t + z3) + b2) / ((z3 - z2) (t - z2)); for t > z3 one minus the weight of t,
//    1 - (z2 z3 - b1 (z2 + z3) + b2) / ((t - z2) (t - z3)).
float hamburger4(vec4 b, float t, float bias) {
    b = mix(b, vec4(0.5), bias);
    // Cholesky B = L D L^T, L unit lower triangular.
    float d1 = 1.0;
    float l21 = b.x, l31 = b.y;
    float d2 = b.y - l21 * l21 * d1;
    float l32 = (b.z - l31 * l21 * d1) / d2;
    float d3 = b.w - l31 * l31 * d1 - l32 * l32 * d2;
    // Forward (L y = z), scale (D w = y), back (L^T c = w).
    vec3 z = vec3(1.0, t, t * t);
    float y1 = z.x, y2 = z.y - l21 * y1, y3 = z.z - l31 * y1 - l32 * y2;
    float w1 = y1 / d1, w2 = y2 / d2, w3 = y3 / d3;
    float c3 = w3, c2 = w2 - l32 * c3, c1 = w1 - l21 * c2 - l31 * c3;
    // c3 z^2 + c2 z + c1 = 0: p = c2 / c3, q = c1 / c3.
    float p = c2 / c3, q = c1 / c3;
    float r = sqrt(max(0.25 * p * p - q, 0.0));
    float z2 = -0.5 * p - r, z3 = -0.5 * p + r;
    if (t <= z2) return 0.0;
    if (t <= z3) return clamp((t * z3 - b.x * (t + z3) + b.y) / ((z3 - z2) * (t - z2)), 0.0, 1.0);
    return clamp(1.0 - (z2 * z3 - b.x * (z2 + z3) + b.y) / ((t - z2) * (t - z3)), 0.0, 1.0);
}
