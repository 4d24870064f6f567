// Test fixture (VulkanTargetsVkTest): one triangle over the lower-left half of NDC (x + y < 0) at depth
// 0.5, from gl_VertexIndex alone (no vertex buffer).
const vec2 kCorners[3] = vec2[3](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0));
void main() {
    gl_Position = vec4(kCorners[gl_VertexIndex], 0.5, 1.0);
}
