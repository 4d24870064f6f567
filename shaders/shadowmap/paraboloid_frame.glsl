// The dual-paraboloid parameterisation (Brabec, Annen, Seidel 2002, Shadow Mapping for Hemispherical
// and Omnidirectional Light Sources; the paraboloid map of Heidrich and Seidel 1998): two hemispheres
// per point light, the front one around -Y (the scene below the light), the back one around +Y. In a
// hemisphere's frame (z along its axis) a unit direction d maps to (d.x, d.y) / (1 + d.z), the whole
// hemisphere (d.z >= 0) to the unit disc; depth is the distance to the light, linear between near
// and far. techniques/shadowmap/ParaboloidGL.cpp uses the same axes for its culling.

// Light-to-point vector `v` (world) in hemisphere `half_`'s frame (0 front, 1 back). Front: x = X,
// y = Z, z = -Y (right-handed); back: the front frame turned 180 degrees about x.
vec3 paraboloidFrame(vec3 v, int half_) {
    vec3 p = vec3(v.x, v.z, -v.y);
    return half_ == 0 ? p : vec3(p.x, -p.y, -p.z);
}

// Unit direction in a hemisphere's frame to map coordinates in [-1, 1]^2 (inside the unit disc).
vec2 paraboloidProject(vec3 d) {
    return d.xy / (1.0 + d.z);
}

// Distance to the light mapped to window depth [0, 1].
float paraboloidDepth(float dist, vec2 nearFar) {
    return (dist - nearFar.x) / (nearFar.y - nearFar.x);
}

// Light-to-point vector `v` (world) to hemisphere `half_`'s clip space, written homogeneously,
// (d.x, d.y, z (1 + d.z), 1 + d.z), so that the GL's clipping interpolates in clip space and a triangle
// crossing the hemisphere's plane is cut where `clipDistance` is 0. The cut lies `beyondRim` (the sine
// of an angle) behind the plane: the map keeps a ring of texels just outside its unit disc, whose
// directions belong to the other half, so that a fragment at the light's height, looked up at the
// rim, finds casters in every texel of its filter footprint instead of the cleared far depth (the
// light would leak along the seam). The depth passes' vertex and geometry stages share it.
vec4 paraboloidClip(vec3 v, int half_, vec2 nearFar, float beyondRim, out float clipDistance) {
    vec3 p = paraboloidFrame(v, half_);
    float dist = length(p);
    vec3 d = dist > 0.0 ? p / dist : vec3(0.0, 0.0, 1.0);
    float w = 1.0 + d.z;
    float z = 2.0 * paraboloidDepth(dist, nearFar) - 1.0;
    clipDistance = d.z + beyondRim;
#ifdef VULKAN
    z = 0.5 * z + 0.5; // Vulkan's clip z runs over [0, w] (VulkanFrameBlock::depthFromGl)
#endif
    return vec4(d.xy, z * w, w);
}
