// Depth pass of the filterable shadow maps (`vsm`, `esm`): casters seen from one light. The world position
// goes to the fragment stage, which computes the linear depth it stores (shadowmap/light_depth.glsl).
#include "common/instance.glsl"

layout(location = 8) uniform mat4 uLightViewProj;
out vec3 vWorldPos;

void main() {
    vec4 world = instanceModel() * vec4(aPosition, 1.0);
    vWorldPos = world.xyz;
    gl_Position = uLightViewProj * world;
}
