// The viewer's overlay (bench/lib/viewer/Overlay.h): quads given in window pixels, y down; mode 0 the
// dimmed box, 1 text, 2 the colour bar.
layout(location = 0) in vec2 aPixel;
layout(location = 1) in vec2 aUv;
layout(location = 2) in float aMode;
uniform vec2 uWindowSize;
out vec2 vUv;
flat out int vMode;
void main() {
    vUv = aUv;
    vMode = int(aMode + 0.5);
    gl_Position = vec4(aPixel.x / uWindowSize.x * 2.0 - 1.0, 1.0 - aPixel.y / uWindowSize.y * 2.0, 0.0, 1.0);
}
