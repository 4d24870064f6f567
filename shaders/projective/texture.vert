// `projective` texture pass: the casters seen from a light's projector (uniform), drawn as a
// silhouette into one layer of the projective texture.
#include "common/instance.glsl"

#ifdef VULKAN
// Set 1 (techniques/projective/ProjectiveVulkan.h): the light's projector, one dynamic slot per light.
layout(std140, set = 1, binding = 0) uniform Projector { mat4 uLightViewProj; };
#else
layout(location = 8) uniform mat4 uLightViewProj;
#endif

void main() { gl_Position = uLightViewProj * (instanceModel() * vec4(aPosition, 1.0)); }
