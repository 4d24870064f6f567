// `synthetic`: flat colour, fully lit (visibility 1 for every light): no shading cost to speak of.
in vec4 vColor;
layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oVisibility;

void main() {
    oColor = vColor;
    oVisibility = vec4(1.0);
}
