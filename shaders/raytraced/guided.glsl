// `raytraced:mode=guided`: whether a light's depth map already decides a shadow ray, so that only the
// unsure are traced. The rule, and why it is conservative, is techniques/raytraced/GuidedRays.h's; the
// maps and this set are techniques/raytraced/GuideMapsVulkan.h's. Included by raytraced/lighting.frag
// under RT_MODE_GUIDED, with GUIDED_RINGS (the `neighbourhood` rings around the 2 x 2 taps) defined.

// Set 2: per light its map's matrix (world to the map's [0, 1] texture space and depth) and what the
// rule needs of it; the map layers; the count of the decisions taken without a ray.
layout(std140, set = 2, binding = 0) uniform GuidedBlock {
    mat4 uGuideMatrix[LIGHT_COUNT];
    // x: world size of a map texel at w = 1 (FlatLightFits::texelWorldSize), y: 1 where the light has
    // a map, z: 1 for a directional light (orthographic map), 0 for a spot light
    vec4 uGuideLight[LIGHT_COUNT];
    // x: `margin` (map texels of world distance along the ray), y: the depth steps every band adds
    vec4 uGuideParams;
};
layout(set = 2, binding = 1) uniform sampler2DArray uGuideMaps; // nearest depths, read by texelFetch
// Pixel-lights the map decided this frame (the `rays_decided` counter: 64 bits in two words,
// raytraced/count64.glsl), zeroed by the frame before the pass.
layout(std430, set = 2, binding = 2) buffer GuidedCount {
    uint uDecided;
    uint uDecidedHigh;
};

const float kGuideUnsure = -1.0;

// The map's texture-space coordinate of world point q and its depth, after the divide; w <= 0 behind a
// spot light.
vec4 guideCoord(int i, vec3 q) {
    vec4 c = uGuideMatrix[i] * vec4(q, 1.0);
    return vec4(c.xyz / c.w, c.w);
}

// The depth slope (dz/du, dz/dv) of the plane through p with unit normal n, seen through light i's map
// at m = guideCoord(i, p): the images of two points of the plane one texel (`step` world units) from p.
// A plane stays a plane under the light's projection, so the slope is exact. False where the plane is
// seen edge-on from the light (no slope to speak of).
bool planeSlope(int i, vec3 p, vec3 n, vec4 m, float step, out vec2 slope) {
    vec3 t1 = normalize(cross(n, abs(n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0)));
    vec3 t2 = cross(n, t1);
    vec3 a = guideCoord(i, p + step * t1).xyz - m.xyz;
    vec3 b = guideCoord(i, p + step * t2).xyz - m.xyz;
    float det = a.x * b.y - a.y * b.x;
    slope = vec2(a.z * b.y - b.z * a.y, a.x * b.z - b.x * a.z) / det;
    return abs(det) > 0.0 && all(lessThan(abs(slope), vec2(1.0e30)));
}

// Light i's visibility at p (geometric normal n, unit vector `towards` the light) where its map decides
// it: 1 surely lit, 0 surely shadowed; kGuideUnsure where a ray must (GuidedRays.h, "The rule").
float guidedVisibility(int i, vec3 p, vec3 n, vec3 towards) {
    if (uGuideLight[i].y == 0.0) return kGuideUnsure; // no map (a point light)
    bool directional = uGuideLight[i].z != 0.0;
    vec4 m = guideCoord(i, p);
    if (!(m.w > 0.0)) return kGuideUnsure;
    bool inside = all(greaterThanEqual(m.xy, vec2(0.0))) && all(lessThanEqual(m.xy, vec2(1.0)));
    if (!inside) return directional ? 1.0 : kGuideUnsure;
    // A texel's world size at p, the receiver's plane in the map and the band around it.
    float texel = uGuideLight[i].x * m.w;
    vec2 slope;
    if (!planeSlope(i, p, n, m, texel, slope)) return kGuideUnsure;
    float band = abs(guideCoord(i, p + towards * (uGuideParams.x * texel)).z - m.z) + uGuideParams.y;
    ivec2 size = textureSize(uGuideMaps, 0).xy;
    ivec2 first = ivec2(floor(m.xy * vec2(size) - 0.5)) - GUIDED_RINGS;
    const int side = 2 + 2 * GUIDED_RINGS;
    int front = 0;
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            ivec2 t = first + ivec2(x, y);
            if (any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, size))) {
                if (!directional) return kGuideUnsure; // a spot's map says nothing there
                continue;                              // no caster outside a directional map
            }
            float d = texelFetch(uGuideMaps, ivec3(t, i), 0).r;
            vec2 uv = (vec2(t) + 0.5) / vec2(size);
            float plane = m.z + dot(slope, uv - m.xy);
            if (d < 1.0 && d < plane - band) ++front; // 1: cleared, no caster on this texel's ray
        }
    if (front == 0) return 1.0;
    if (front == side * side) return 0.0;
    return kGuideUnsure;
}

// Decisions this fragment took without a ray (added to uDecided once, at the end of the fragment).
uint gGuideDecided = 0u;

// The visibility of light i where its shadow is asked for: the map's decision, else hard's ray.
float guidedOrTraced(int i, vec3 p, vec3 n, vec3 towards, inout uint rays) {
    float decided = guidedVisibility(i, p, n, towards);
    if (decided != kGuideUnsure) {
        ++gGuideDecided;
        return decided;
    }
    return traceCentre(i, p, n, towards, true, rays);
}
