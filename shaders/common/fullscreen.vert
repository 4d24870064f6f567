// Full-screen triangle from the vertex index (no vertex buffers): the timer calibration's fill workload,
// `synthetic`'s fill pass and `projective`'s blur passes.
#ifdef VULKAN
#define SB_VERTEX_INDEX gl_VertexIndex
#else
#define SB_VERTEX_INDEX gl_VertexID
#endif
void main() {
    vec2 p = vec2((SB_VERTEX_INDEX << 1) & 2, SB_VERTEX_INDEX & 2);
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
