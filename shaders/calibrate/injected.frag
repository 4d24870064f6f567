// The perf gate's injected regression "extra_fullscreen_pass" (core/Injection.h): a full-screen pass an
// engine change might add by mistake. It multiplies the colour by one (blended), so the image is kept
// while every pixel is shaded and blended once more.
layout(location = 0) out vec4 oColor;

void main() {
    oColor = vec4(1.0);
}
