// A fixed amount of arithmetic per invocation: `iterations` steps of a small trigonometric map whose
// result is returned, so the caller can feed it into an output and the compiler cannot drop the loop.
// Shared by the timer calibration's fill workload and the `synthetic` technique.
float aluLoop(vec2 p, int iterations) {
    float acc = 0.0;
    for (int i = 0; i < iterations; ++i) {
        p = vec2(sin(p.x * 1.7 + p.y), cos(p.y * 1.3 - p.x));
        acc += p.x * p.y;
    }
    return acc;
}
