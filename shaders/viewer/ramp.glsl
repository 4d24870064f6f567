// The viewer's false-colour ramp for visibility (bench/lib/viewer/VisibilityView.h): dark blue (0, shadowed)
// through purple and orange to pale yellow (1, lit); NaN magenta, anything outside [0, 1] green.
vec3 sbVisibilityRamp(float v) {
    if (isnan(v)) return vec3(1.0, 0.0, 1.0);
    if (!(v >= 0.0 && v <= 1.0)) return vec3(0.0, 1.0, 0.0);
    const vec3 stops[4] = vec3[4](vec3(0.05, 0.03, 0.30), vec3(0.55, 0.10, 0.55), vec3(0.95, 0.50, 0.15),
                                  vec3(1.00, 0.97, 0.75));
    float t = v * 3.0;
    int i = min(int(t), 2);
    return mix(stops[i], stops[i + 1], t - float(i));
}
