// `cubemap` layered depth pass, vertex stage: world position only; the geometry stage projects it
// into each face it may touch (cube_depth.geom). `paraboloid`'s splitting stage takes the same input
// (paraboloid_split.geom).
#include "common/instance.glsl"

out vec4 vWorld;

void main() {
    vWorld = instanceModel() * vec4(aPosition, 1.0);
}
