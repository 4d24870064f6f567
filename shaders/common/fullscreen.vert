// Full-screen triangle from gl_VertexID (no vertex buffers): the timer calibration's fill workload,
// `synthetic`'s fill pass and `projective`'s blur passes.
void main() {
    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
