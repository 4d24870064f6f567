// Test fixture: a function the main shaders include.
#ifndef FILL_RED
#define FILL_RED 1.0
#endif
vec4 testColor() {
    return vec4(FILL_RED, 0.5, 0.25, 1.0);
}
