// Test fixture: passes compatibility-profile vertices through (immediate mode / fullscreen quads).
void main() {
    gl_Position = gl_Vertex;
}
