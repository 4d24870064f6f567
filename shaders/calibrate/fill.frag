// A fragment-bound loop whose cost is the same for every pixel, so frame cost is proportional to the
// pixel count. The result feeds the output so the loop cannot be optimised away.
layout(location = 0) uniform int uIterations;
layout(location = 0) out vec4 oColor;

void main() {
    vec2 p = gl_FragCoord.xy * 0.001;
    float acc = 0.0;
    for (int i = 0; i < uIterations; ++i) {
        p = vec2(sin(p.x * 1.7 + p.y), cos(p.y * 1.3 - p.x));
        acc += p.x * p.y;
    }
    oColor = vec4(fract(acc), p, 1.0);
}
