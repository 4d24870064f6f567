// `reference` shade pass: lit like common/lit.frag, each light's term multiplied by the ray-traced
// visibility uploaded per frame (RGBA32F, channel i = light i, at this pixel). The pass re-rasterises
// the G-buffer's triangles with the same camera, so gl_FragCoord names this fragment's own sample.
#include "common/frame.glsl"
#include "common/lighting.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vColorId;
layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oVisibility;

#ifdef VULKAN
// Set 1 after the frame block (reference/ReferenceVulkan.h), uploaded with Vulkan's row order, so the
// fragment's own coordinates (origin at the top) fetch its sample too.
layout(set = 1, binding = 0) uniform sampler2D uVisibility;
#else
layout(binding = 0) uniform sampler2D uVisibility;
#endif

void main() {
    vec4 traced = texelFetch(uVisibility, ivec2(gl_FragCoord.xy), 0);
    // -1 marks samples without geometry in the G-buffer: treated as lit, like the cleared target.
    vec4 vis = mix(traced, vec4(1.0), lessThan(traced, vec4(0.0)));
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing) n = -n;
    vec3 light = ambientLight();
    for (int i = 0; i < LIGHT_COUNT; ++i) light += vis[i] * lightTerm(i, vWorldPos, n);
    oColor = vec4(vColorId.rgb * light, 1.0);
    oVisibility = vis;
}
