// `cubemap` layered depth pass: one pass per light renders all six faces (Gerasimov 2004, GPU Gems
// ch. 12, renders one pass per face; a geometry shader with gl_Layer does the six in one). Each
// triangle goes only to the faces whose frustum it may touch: it is dropped from a face when all
// three vertices lie outside one plane of that face's clip volume (the conservative outcode test of
// scenes/InstanceCulling, per triangle). Layer = uLayerBase + face, uLayerBase = 6 * the
// light's cube in the GL_TEXTURE_CUBE_MAP_ARRAY; face order +X, -X, +Y, -Y, +Z, -Z.
layout(triangles) in;
layout(triangle_strip, max_vertices = 18) out;

in vec4 vWorld[];

#ifdef VULKAN
// One slot per cube of a dynamic uniform buffer (techniques/shadowmap/CubeMapVulkan.h).
layout(std140, set = 1, binding = 0) uniform CubePass {
    mat4 uFaceViewProj[6];
    int uLayerBase;
};
#else
layout(location = 12) uniform mat4 uFaceViewProj[6]; // techniques/shadowmap/CubeFaces.h
layout(location = 18) uniform int uLayerBase;
#endif

// Bit k: outside plane k (x < -w, x > w, y < -w, y > w, z < -w, z > w).
uint outcode(vec4 p) {
    uint c = 0u;
    c |= p.x < -p.w ? 1u : 0u;
    c |= p.x > p.w ? 2u : 0u;
    c |= p.y < -p.w ? 4u : 0u;
    c |= p.y > p.w ? 8u : 0u;
    c |= p.z < -p.w ? 16u : 0u;
    c |= p.z > p.w ? 32u : 0u;
    return c;
}

void main() {
    for (int face = 0; face < 6; ++face) {
        vec4 p0 = uFaceViewProj[face] * vWorld[0];
        vec4 p1 = uFaceViewProj[face] * vWorld[1];
        vec4 p2 = uFaceViewProj[face] * vWorld[2];
        if ((outcode(p0) & outcode(p1) & outcode(p2)) != 0u) continue;
        gl_Layer = uLayerBase + face;
        gl_Position = p0;
        EmitVertex();
        gl_Layer = uLayerBase + face;
        gl_Position = p1;
        EmitVertex();
        gl_Layer = uLayerBase + face;
        gl_Position = p2;
        EmitVertex();
        EndPrimitive();
    }
}
