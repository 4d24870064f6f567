// `volume` ambient pass (GPU Gems ch. 9, section 9.2.1): ambient light only, writes depth for the
// light passes. Visibility starts at 0 for every light; each light pass adds 1 where it lights.
#include "common/frame.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vColorId;
layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oVisibility;

void main() {
    oColor = vec4(vColorId.rgb * uAmbient.rgb, 1.0);
    int lights = frameLightCount();
    oVisibility = vec4(lights > 0 ? 0.0 : 1.0, lights > 1 ? 0.0 : 1.0, lights > 2 ? 0.0 : 1.0,
                       lights > 3 ? 0.0 : 1.0);
}
