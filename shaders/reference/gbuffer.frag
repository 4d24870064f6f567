// `reference` G-buffer pass: xyz world position + object id (RGBA32F), triangle index within the draw
// (R32UI; gl_PrimitiveID restarts per draw and per instance of an instanced draw) with bit 31 set on a
// back face (gl_FrontFacing false: the side the technique shaded, reference/GBuffer.h backFacing).
in vec3 vWorldPos;
flat in float vObjectId;
layout(location = 0) out vec4 oPosition;
layout(location = 1) out uint oPrimitive;

void main() {
    oPosition = vec4(vWorldPos, vObjectId);
    oPrimitive = uint(gl_PrimitiveID) | (gl_FrontFacing ? 0u : 0x80000000u);
}
