// Per-frame data shared by every technique (std140 UBO, binding 0), written once per frame by the
// harness (techniques/gl/FrameUniforms, techniques/vulkan/VulkanFrameBlock). Mirrors struct FrameUniformData in techniques/FrameBlock.h.
layout(std140, binding = 0) uniform Frame {
    mat4 uView;
    mat4 uProj;
    mat4 uViewProj;
    vec4 uEye;                 // xyz: camera position (world)
    vec4 uAmbient;             // rgb: ambient colour; w: number of lights
    vec4 uLightPos[4];         // xyz: position (point/spot); w: type 0 directional, 1 point, 2 spot
    vec4 uLightDir[4];         // xyz: unit direction from the light into the scene; w: cos(outer)
    vec4 uLightColor[4];       // rgb: colour * intensity; w: range (0 = unlimited)
    vec4 uLightParams[4];      // x: cos(inner)
};

int frameLightCount() { return int(uAmbient.w); }
