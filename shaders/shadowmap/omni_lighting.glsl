// The lighting pass shared by `cubemap` and `paraboloid` (included after common/frame.glsl,
// common/lighting.glsl and common/contact_shadow.glsl, whose contactLimited is the `contact` march): per
// light, the visibility from its map (Williams 1978), times its unshadowed term. uMap[i] = (kind, layer):
// MAP_NONE (lit: no map, e.g. a point light whose range reaches no caster), MAP_FLAT (the spot or
// directional map of `shadowmap`, in the 2D depth array uFlatMaps at `layer`) or MAP_OMNI (the point
// light's omni map; omniVisibility() is the including technique's, defined after this file). PCF_SIZE x
// PCF_SIZE taps, one texel apart, each a hardware depth compare with bilinear filtering of the comparison
// results.
#define MAP_NONE 0
#define MAP_FLAT 1
#define MAP_OMNI 2

in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vColorId;
in vec4 vShadowCoord[LIGHT_COUNT];
layout(location = 0) out vec4 oColor;
layout(location = 1) out vec4 oVisibility;

#ifdef VULKAN
// Set 1 (techniques/shadowmap/CubeMapVulkan.h): the uniforms GL sets by location, in one block whose
// head common/scene.vert reads. std140: each ivec2 and vec2 of an array takes 16 bytes.
layout(std140, set = 1, binding = 0) uniform ShadowMapBlock {
    mat4 uShadowMatrix[LIGHT_COUNT];
    ivec2 uMap[LIGHT_COUNT];       // (kind, layer)
    vec2 uDepthRange[LIGHT_COUNT]; // omni maps: (near, far)
};
#else
layout(location = 16) uniform ivec2 uMap[LIGHT_COUNT];       // (kind, layer)
layout(location = 20) uniform vec2 uDepthRange[LIGHT_COUNT]; // omni maps: (near, far)
#endif

/// Visibility of light `light` at the fragment from its omni map (first layer `layer`), `fromLight`
/// the vector from the light to the fragment, `nearFar` the map's depth range.
float omniVisibility(int light, int layer, vec3 fromLight, vec2 nearFar);

#ifdef FLAT_MAPS
#ifdef VULKAN
layout(set = 1, binding = 1) uniform sampler2DArrayShadow uFlatMaps;
#else
layout(binding = 0) uniform sampler2DArrayShadow uFlatMaps;
#endif

// As shaders/shadowmap/lighting.frag's visibility(), with hardware compare.
float flatVisibility(int layer, vec4 coord) {
    if (coord.w <= 0.0) return 1.0; // behind a spot light: its term is zero anyway
    vec3 p = coord.xyz / coord.w;
    if (any(lessThan(p.xy, vec2(0.0))) || any(greaterThan(p.xy, vec2(1.0))) || p.z > 1.0) return 1.0;
    vec2 texel = 1.0 / vec2(textureSize(uFlatMaps, 0).xy);
    const float half_ = 0.5 * float(PCF_SIZE - 1);
    float sum = 0.0;
    for (int y = 0; y < PCF_SIZE; ++y)
        for (int x = 0; x < PCF_SIZE; ++x)
            sum += texture(uFlatMaps, vec4(p.xy + (vec2(x, y) - half_) * texel, float(layer), p.z));
    return sum / float(PCF_SIZE * PCF_SIZE);
}
#endif

float lightVisibility(int i) {
#ifdef FLAT_MAPS
    if (uMap[i].x == MAP_FLAT) return flatVisibility(uMap[i].y, vShadowCoord[i]);
#endif
#ifdef OMNI_MAPS
    if (uMap[i].x == MAP_OMNI)
        return omniVisibility(i, uMap[i].y, vWorldPos - uLightPos[i].xyz, uDepthRange[i]);
#endif
    return 1.0;
}

void main() {
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing) n = -n;
    vec3 light = ambientLight();
    vec4 vis = vec4(1.0);
    for (int i = 0; i < LIGHT_COUNT; ++i) {
        vis[i] = shadowApplies(i, vColorId) ? contactLimited(i, lightVisibility(i), vWorldPos, n) : 1.0;
        light += vis[i] * lightTerm(i, vWorldPos, n);
    }
    oColor = vec4(vColorId.rgb * light, 1.0);
    oVisibility = vis;
}
