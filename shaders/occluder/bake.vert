// Occluder-texture bake (techniques/occluder/OccluderTextures.cpp): an orthographic view along the shadow
// plane's normal onto its [0, 1]^2 texture square (equation 8 of the thesis), one texel per pixel.
// BAKE_CLIP: the cross-section's marking pass, clipped to the normal's side of the plane (only this
// permutation writes gl_ClipDistance: llvmpipe clips on a written distance even with
// GL_CLIP_DISTANCE0 disabled, which would cut the silhouette in half).
// BAKE_FULLSCREEN: a full-screen triangle from gl_VertexID instead (the stencil-tested fill pass).
#ifdef BAKE_FULLSCREEN
void main() {
#ifdef VULKAN
    int id = gl_VertexIndex;
#else
    int id = gl_VertexID;
#endif
    vec2 p = vec2((id << 1) & 2, id & 2);
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
#else
layout(location = 0) in vec3 aPosition;
#ifdef VULKAN
// techniques/occluder/OccluderBakeVulkan.h: GL's uniforms as push constants (std430: each vec3 16 bytes).
layout(push_constant) uniform BakePush {
    vec3 uOrigin;
    vec3 uRight;
    vec3 uUp;
    vec3 uNormal;
};
#else
layout(location = 0) uniform vec3 uOrigin; // texture (0, 0) corner
layout(location = 1) uniform vec3 uRight;  // right / width: u = dot(uRight, p - uOrigin)
layout(location = 2) uniform vec3 uUp;     // up / height
layout(location = 3) uniform vec3 uNormal; // unit
#endif

void main() {
    vec3 d = aPosition - uOrigin;
    vec2 uv = vec2(dot(uRight, d), dot(uUp, d));
    gl_Position = vec4(uv * 2.0 - 1.0, 0.0, 1.0);
#ifdef BAKE_CLIP
    // Signed distance from the plane: only the normal's side of the plane is drawn.
    gl_ClipDistance[0] = dot(uNormal, d);
#endif
}
#endif
