// `paraboloid` depth pass, geometry stage for casters whose edges span wide angles seen from the
// light: each triangle is cut into an n x n grid of similar triangles and every grid vertex inside it
// is projected exactly (paraboloidClip, paraboloid_frame.glsl). A straight caster edge maps to a
// circular arc in the paraboloid map (the projection is stereographic), which a segment of angle a
// follows within a sagitta of a^2 / 8 map units; uMaxAngle keeps it under half a texel
// (techniques/shadowmap/ParaboloidSplitting.h). The same bound keeps the depth between grid vertices,
// linear where the true distance is not, within 1 - cos(a / 2) of the distance, and the clipping at
// the hemisphere's plane, which joins the cut points by a chord of the rim, within the same half
// texel. A triangle wholly behind the cut (paraboloidClip) emits nothing.
//
// Watertight: each edge is cut into its own count of segments, ceil(its angle / uMaxAngle) clamped
// to kMaxSegments, computed from its endpoints in a fixed order, so the two triangles that share an
// edge cut it at the same points, bit for bit. The grid's n is the largest of the three counts; a
// grid vertex on an edge with fewer segments is placed on that edge's polyline (a clip-space mix of
// the two segment ends, which lies on the drawn segment), not on the arc, or a neighbour's coarser
// chord would leave a crack that light leaks through (a closed caster around the light).
//
// One invocation emits the grid's rows as triangle strips (row r: 2 (n - r) + 1 vertices, n^2 + 2n in
// all): at n = 13, 195 vertices of 5 components, within the 1024 output components every GL 4.5
// context allows. Edges wider than 13 segments' worth (46 degrees at 2048^2) are cut into 13 and keep
// a sagitta of (angle / 13)^2 * resolution / 16 texels (2.3 texels for a 99 degree edge at 2048^2).
// Not split across instanced invocations: llvmpipe runs its geometry stage inside the draw call,
// and with 8 invocations of 99 vertices (n up to 24) the room's depth pass took 21-25 ms of CPU
// against 1.4 ms with one invocation of 195, for the same error.
#include "shadowmap/paraboloid_frame.glsl"

layout(triangles) in;
layout(triangle_strip, max_vertices = 195) out;

const int kMaxSegments = 13;

in vec4 vWorld[];

#ifdef VULKAN
// One slot per hemisphere of a dynamic uniform buffer (techniques/shadowmap/ParaboloidVulkan.h).
layout(std140, set = 1, binding = 0) uniform ParaboloidPass {
    vec4 uLight; // xyz: position; w: hemisphere (0 front, 1 back)
    vec2 uNearFar;
    float uMaxAngle;  // radians a segment may span (paraboloid_split.geom)
    float uBeyondRim; // the clip plane's offset behind the hemisphere's
};
#else
layout(location = 8) uniform vec4 uLight; // xyz: position; w: hemisphere (0 front, 1 back)
layout(location = 12) uniform vec2 uNearFar;
layout(location = 13) uniform float uMaxAngle; // radians a segment may span
layout(location = 14) uniform float uBeyondRim; // the clip plane's offset behind the hemisphere's
#endif

#ifdef VULKAN
// Position and clip distance only: 5 components a vertex, 975 in all (the limit is 1024), where the
// implicit block's point size and cull distance would count too.
out gl_PerVertex {
    vec4 gl_Position;
    float gl_ClipDistance[1];
};
#else
out float gl_ClipDistance[1];
#endif

vec3 gA, gB, gC; // the triangle's corners, light-relative
int gN;          // grid segments per side

// The angle between two directions from the light, accurate for small and near-opposite pairs.
float angleBetween(vec3 a, vec3 b) {
    return atan(length(cross(a, b)), dot(a, b));
}

// An edge's segment count, the same whichever triangle asks (its endpoints in canonical order).
int segmentsOf(vec3 p, vec3 q) {
    return clamp(int(ceil(angleBetween(p, q) / uMaxAngle)), 1, kMaxSegments);
}

bool precedes(vec3 p, vec3 q) {
    return p.x != q.x ? p.x < q.x : (p.y != q.y ? p.y < q.y : p.z < q.z);
}

// Wholly behind the cut (the cone of directions more than the rim's ring behind the plane, convex,
// so a triangle with its three corners there lies there whole).
bool behind(vec3 v) {
    return paraboloidFrame(v, int(uLight.w)).z < -uBeyondRim * length(v);
}

vec4 project(vec3 v, out float clipDistance) {
    return paraboloidClip(v, int(uLight.w), uNearFar, uBeyondRim, clipDistance);
}

// Point k of an edge cut into `segments`, its ends exact.
vec3 edgeVertex(vec3 p, vec3 q, int k, int segments) {
    return k == 0 ? p : (k == segments ? q : p + (q - p) * (float(k) / float(segments)));
}

// Grid point m of gN along the edge from p to q, on that edge's own polyline.
vec4 edgePoint(vec3 p, vec3 q, int m, out float clipDistance) {
    if (precedes(q, p)) {
        vec3 t = p;
        p = q;
        q = t;
        m = gN - m;
    }
    int segments = segmentsOf(p, q);
    int k = (m * segments) / gN;
    int rest = m * segments - k * gN;
    vec4 c0 = project(edgeVertex(p, q, k, segments), clipDistance);
    if (rest == 0) return c0;
    float d1;
    vec4 c1 = project(edgeVertex(p, q, k + 1, segments), d1);
    float f = float(rest) / float(gN);
    clipDistance = mix(clipDistance, d1, f);
    return mix(c0, c1, f);
}

// Grid vertex (i, j): i steps towards c and j towards b, so that each strip's first triangle
// (a, a + j, a + i) keeps the winding of (a, b, c).
void emit(int i, int j) {
    float clipDistance;
    if (j == 0)
        gl_Position = edgePoint(gA, gC, i, clipDistance);
    else if (i == 0)
        gl_Position = edgePoint(gA, gB, j, clipDistance);
    else if (i + j == gN)
        gl_Position = edgePoint(gB, gC, i, clipDistance);
    else
        gl_Position = project(gA + (gC - gA) * (float(i) / float(gN)) + (gB - gA) * (float(j) / float(gN)),
                              clipDistance);
    gl_ClipDistance[0] = clipDistance;
    EmitVertex();
}

void main() {
    gA = vWorld[0].xyz - uLight.xyz;
    gB = vWorld[1].xyz - uLight.xyz;
    gC = vWorld[2].xyz - uLight.xyz;
    if (behind(gA) && behind(gB) && behind(gC)) return;
    gN = max(segmentsOf(precedes(gA, gB) ? gA : gB, precedes(gA, gB) ? gB : gA),
             max(segmentsOf(precedes(gB, gC) ? gB : gC, precedes(gB, gC) ? gC : gB),
                 segmentsOf(precedes(gA, gC) ? gA : gC, precedes(gA, gC) ? gC : gA)));
    for (int r = 0; r < gN; ++r) {
        for (int i = 0; i < gN - r; ++i) {
            emit(i, r);
            emit(i, r + 1);
        }
        emit(gN - r, r);
        EndPrimitive();
    }
}
