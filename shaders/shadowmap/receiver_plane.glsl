// Receiver-plane depth bias (Isidoro 2006, Shadow Mapping: GPU-based Tips and Techniques, GDC 2006,
// "Receiver Plane Depth Bias"): the receiver is taken to be locally a plane in light space, depth =
// z + dz/du du + dz/dv dv, with dz/du and dz/dv solved from the screen-space derivatives of the shadow
// coordinate (u, v, z) by the chain rule:
//   [du/dx dv/dx] [dz/du]   [dz/dx]
//   [du/dy dv/dy] [dz/dv] = [dz/dy]
// so every filter tap at offset o (in u, v) compares against the receiver's own depth there, z + dot(slope,
// o), instead of the centre's, and a wide kernel on a sloped receiver does not shadow the receiver itself.
// The derivatives must be taken in uniform control flow: callers evaluate receiverSlope() before any
// branch. A degenerate footprint (the receiver seen edge-on in the map, or a 2x2 quad straddling a
// silhouette with a zero determinant) gets slope 0: plain comparison there.

vec2 receiverSlope(vec3 p) {
    vec3 dx = dFdx(p), dy = dFdy(p);
    float det = dx.x * dy.y - dx.y * dy.x;
    if (!(abs(det) > 1e-30)) return vec2(0.0);
    vec2 slope = vec2(dy.y * dx.z - dx.y * dy.z, dx.x * dy.z - dy.x * dx.z) / det;
    // Non-finite slopes (overflowed products) fall back to plain comparison as well.
    return all(lessThan(abs(slope), vec2(1e30))) ? slope : vec2(0.0);
}

// The map holds each texel's depth at the texel centre, up to one texel away from the lookup point in u and
// v, and the bilinear compare reads a 2x2 footprint: the receiver plane may move by its slope over two
// texels before the comparison reaches the stored depth. Subtracting that change (capped at 0.01 of the
// depth range, so a silhouette's huge slope cannot push the receiver through its casters) removes the
// quantisation acne a plane evaluated at the lookup point alone would keep.
float receiverQuantisation(vec2 slope, vec2 texel) {
    return min(2.0 * dot(texel, abs(slope)), 0.01);
}
