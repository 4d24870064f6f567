// Linear light-space depth in [0, 1] of filterable shadow maps (techniques/shadowmap/FilterableShadowMaps.h):
// what `vsm` and `esm` store per caster fragment and compare each receiver with. Directional lights: the
// orthographic map's depth, a plane (d = dot(plane.xyz, p) + plane.w; point.w = 0). Spot lights: the
// distance to the light over the scene's farthest distance from it (point = light position, 1 / dMax).
float lightDepth(vec4 plane, vec4 point, vec3 worldPos) {
    if (point.w > 0.0) return length(worldPos - point.xyz) * point.w;
    return dot(plane.xyz, worldPos) + plane.w;
}

// The map coordinate of a shadow coordinate (bias * light view-projection * world). False where the map
// says nothing: behind a spot light (w <= 0) or outside [margin, 1 - margin]^2, the border of
// (blur / 2 + 1) texels that holds no caster and whose filtered reads would run off the map
// (FilterableShadowMaps.h, "The margin"): lit.
bool mapCoordinate(vec4 coord, float margin, out vec2 uv) {
    uv = vec2(0.0);
    if (coord.w <= 0.0) return false;
    uv = coord.xy / coord.w;
    return all(greaterThanEqual(uv, vec2(margin))) && all(lessThanEqual(uv, vec2(1.0 - margin)));
}
