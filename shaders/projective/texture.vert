// `projective` texture pass: the casters seen from a light's projector (uniform), drawn as a
// silhouette into one layer of the projective texture.
#include "common/instance.glsl"

layout(location = 8) uniform mat4 uLightViewProj;

void main() { gl_Position = uLightViewProj * (instanceModel() * vec4(aPosition, 1.0)); }
