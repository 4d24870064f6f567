// `shadowmap` depth pass: casters seen from light LIGHT_INDEX (uniform). Depth only.
#include "common/instance.glsl"

layout(location = 8) uniform mat4 uLightViewProj;

void main() { gl_Position = uLightViewProj * (instanceModel() * vec4(aPosition, 1.0)); }
