// Shadow rays from a rasterised surface point through GL_EXT_ray_query (techniques/raytraced/): where a
// ray starts and whether anything stops it. The including stage enables GL_EXT_ray_query and declares
// uScene, the top-level acceleration structure (techniques/raytraced/AccelerationStructures.h).

// Where a ray leaving the surface at p, on the side of unit geometric normal n, starts: Waechter and
// Binder, "A Fast and Robust Method for Avoiding Self-Intersection" (Ray Tracing Gems, ch. 6). Each
// coordinate moves along n by a whole number of units in the last place of that coordinate, 256 n_i of
// them, so the offset scales with the coordinate's own float spacing: as robust at 1e5 as at 1, with
// no scene-dependent epsilon. Near zero, where float spacing vanishes and the error of p does not, a
// coordinate below 1/32 in magnitude moves by a fixed n_i / 65536 instead. The three constants are the
// chapter's. p here is the rasteriser's interpolated world position, which lies a few ulps off its
// triangle (as the chapter's hit point from barycentrics does); 256 ulps keeps it clear.
const float kOffsetOrigin = 1.0 / 32.0;
const float kOffsetFloatScale = 1.0 / 65536.0;
const float kOffsetIntScale = 256.0;

vec3 offsetRayOrigin(vec3 p, vec3 n) {
    ivec3 ulps = ivec3(kOffsetIntScale * n);
    // Adding to the bit pattern moves away from zero; a negative coordinate moves the other way.
    ivec3 signedUlps = mix(ulps, -ulps, lessThan(p, vec3(0.0)));
    vec3 byUlps = intBitsToFloat(floatBitsToInt(p) + signedUlps);
    vec3 byFloat = p + kOffsetFloatScale * n;
    return mix(byUlps, byFloat, lessThan(abs(p), vec3(kOffsetOrigin)));
}

// Whether anything opaque in uScene lies on the ray o + t d, 0 <= t <= tMax: the first hit ends the
// traversal (a shadow ray needs no closest hit) and no hit is handed to the shader (every geometry
// is opaque).
bool occluded(vec3 o, vec3 d, float tMax) {
    rayQueryEXT query;
    rayQueryInitializeEXT(query, uScene, gl_RayFlagsTerminateOnFirstHitEXT | gl_RayFlagsOpaqueEXT, 0xFF, o, 0.0,
                          d, tMax);
    while (rayQueryProceedEXT(query)) {
    }
    return rayQueryGetIntersectionTypeEXT(query, true) != gl_RayQueryCommittedIntersectionNoneEXT;
}
