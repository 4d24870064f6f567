// `projective` texture pass: casters are black (0 = shadowed) on the white (1 = lit) clear colour.
layout(location = 0) out vec4 oValue;

void main() { oValue = vec4(0.0); }
