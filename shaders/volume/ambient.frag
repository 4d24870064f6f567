// `volume` ambient pass (GPU Gems ch. 9, section 9.2.1): ambient light only, writes depth for the
// light passes. Visibility means shadowing only: for each light 0 where its light pass will run (it
// adds 1 where the stencil count is 0), and 1 where it will not (outside its scissor rectangle or
// depth bounds: beyond the light's range nothing is shadowed, the range is a lighting term).
#include "common/frame.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vColorId;
layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oVisibility;
layout(location = 13) uniform ivec4 uLitRect[4];  // per light: pixels x0, y0 (inclusive), x1, y1 (exclusive)
layout(location = 17) uniform vec2 uDepthRange[4]; // per light: window depth bounds of the light pass

// 1 when light i's pass does not run at this fragment (or there is no light i), else 0.
float unshadowed(int i) {
    if (i >= frameLightCount()) return 1.0;
    ivec2 p = ivec2(gl_FragCoord.xy);
    bool inRect = all(greaterThanEqual(p, uLitRect[i].xy)) && all(lessThan(p, uLitRect[i].zw));
    bool inDepth = gl_FragCoord.z >= uDepthRange[i].x && gl_FragCoord.z <= uDepthRange[i].y;
    return inRect && inDepth ? 0.0 : 1.0;
}

void main() {
    oColor = vec4(vColorId.rgb * uAmbient.rgb, 1.0);
    oVisibility = vec4(unshadowed(0), unshadowed(1), unshadowed(2), unshadowed(3));
}
