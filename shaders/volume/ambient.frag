// `volume` ambient pass (GPU Gems ch. 9, section 9.2.1): ambient light only, writes depth for the
// light passes. Visibility means shadowing only: for each light 0 where its light pass will run (it
// adds 1 where the stencil count is 0), and 1 where it will not (outside its scissor rectangle or
// depth bounds: beyond the light's range nothing is shadowed, the range is a lighting term).
#include "common/frame.glsl"
// Not for its light terms (ambient only): common/scene.vert feeds this stage, and under `--lighting
// vertex` its first varyings are the terms (common/lighting.glsl), which Vulkan numbers by declaration
// order: declared here as well, the varyings below keep the vertex stage's locations.
#include "common/lighting.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vColorId;
layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oVisibility;
#ifdef VULKAN
// Set 1 (techniques/volume/VolumeVulkan.h): GL's uniforms in one block. std140: each vec2 of the array
// takes 16 bytes.
layout(std140, set = 1, binding = 0) uniform VolumeAmbient {
    ivec4 uLitRect[4];
    vec2 uDepthRange[4];
    float uTargetHeight; // pixels: gl_FragCoord's y from the bottom, as on GL
};
#else
layout(location = 13) uniform ivec4 uLitRect[4];  // per light: pixels x0, y0 (inclusive), x1, y1 (exclusive)
layout(location = 17) uniform vec2 uDepthRange[4]; // per light: window depth bounds of the light pass
#endif

// 1 when light i's pass does not run at this fragment (or there is no light i), else 0.
float unshadowed(int i) {
    if (i >= frameLightCount()) return 1.0;
    ivec2 p = ivec2(gl_FragCoord.xy);
#ifdef VULKAN
    p.y = int(uTargetHeight - gl_FragCoord.y); // GL's lower-left origin: the rectangles are GL's
#endif
    bool inRect = all(greaterThanEqual(p, uLitRect[i].xy)) && all(lessThan(p, uLitRect[i].zw));
    bool inDepth = gl_FragCoord.z >= uDepthRange[i].x && gl_FragCoord.z <= uDepthRange[i].y;
    return inRect && inDepth ? 0.0 : 1.0;
}

void main() {
    oColor = vec4(vColorId.rgb * ambientLight(), 1.0);
    oVisibility = vec4(unshadowed(0), unshadowed(1), unshadowed(2), unshadowed(3));
}
