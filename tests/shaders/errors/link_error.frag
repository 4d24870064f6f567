// Test fixture: compiles, but calls a function no stage defines, so linking fails.
layout(location = 0) out vec4 oColor;
vec4 undefinedElsewhere();
void main() {
    oColor = undefinedElsewhere();
}
