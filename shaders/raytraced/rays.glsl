// Shadow rays from a rasterised surface point through GL_EXT_ray_query (techniques/raytraced/): where a
// ray starts and whether anything stops it. The including stage enables GL_EXT_ray_query and declares
// uScene, the top-level acceleration structure (techniques/raytraced/AccelerationStructures.h).

// Where a ray leaving the surface at p, on the side of unit geometric normal n, starts: p moved along n by
//   max(1e-4, 32 sum_i |n_i| spacing(p_i)),   spacing(x): from |x| to the next float.
// Waechter and Binder's principle ("A Fast and Robust Method for Avoiding Self-Intersection", Ray Tracing
// Gems, ch. 6: the error of each coordinate follows that coordinate's float spacing, so no
// scene-dependent epsilon) taken as one distance along n; the Embree reference's rule on purpose
// (reference/ReferenceTracer.cpp, originEpsilon): both trace from the same rasterised samples, so with
// the same origins they differ only where traversal or geometry does.
//
// What p misses the traced surface by. p is vWorldPos: model * position in float, interpolated. The bottom
// levels hold the object-space vertices exactly, and for an instance that only translates the ray query takes
// the origin minus the translation exactly (two floats within a factor 2 of each other subtract without
// rounding), so against the traced triangle p is off by the rounding of model * position (half a spacing of
// each world coordinate: 3.9e-3 at 1e5) and the rasteriser's interpolation (a few spacings). The eye-relative
// position (common/scene.vert) is exact after that rounding, but a world origin made from it rounds again:
// from uEye + vEyeRelativePos the chapter's form below left 16 samples off the edge band wrong at 1e5 with 16
// ulps (27 from vWorldPos) and none with 32 (4), the same threshold within a factor 2. Where an instance
// rotates or scales, the model matrix and the ray query's world-to-object transform mix the coordinates, so
// each carries errors of the largest one's spacing, and near the origin the spacings vanish while those
// errors do not: the floor of 1e-4 covers them. An error e_i in coordinate i moves p off the plane by |n_i|
// e_i: covering every e_i <= 32 spacing(p_i) takes the sum above.
//
// The chapter's own form moved coordinate i by int(256 n_i) of its own spacings (n_i / 65536 below
// 1/32), a distance 256 n_i^2 spacing(p_i) along n: nothing where |n_i| < 1/256, short of |n_i| e_i
// where n_i is small and p_i large, too little near the origin when an instance rotates, and at 1e5 up
// to 2 units along an axis, past an aircraft's skins. Measured (bench --driver mesa-25.0.7 accuracy
// --api vulkan -t raytraced:mode=hard --no-stability; samples wrong / of them off the 1-px edge band):
//   tests/hard/scenes/large_coordinates (top, 384^2, 147304 judged: a sphere above a ground at 1e5):
//     this form with 2 spacings 52/42, 4 and up 7/0; the chapter's with 16 ulps 33/27, 32 10/4,
//     64 to 256 6/0 (acne on the sphere where n_x or n_z is small).
//   the 12 built-in scenes, their default camera (summed; 128^2: 118723 judged, 512^2: 1898712): this form
//     0/0 and 5/0 (the floor rules there: 2 to 32 spacings the same); with a floor of 1/65536 3/2 and
//     22/8; the chapter's 16 ulps 22/14 and 346/242, 64 5/4 and 31/16, 256 0/0 and 17/2 (the
//     reference's lift past a neighbour at a crease: aircraft and aircraft_day, one each).
//   teapot, camera mid (the golden matrix's), 128^2, pixel (24, 80): p lies on a lid patch 7.2e-5 under
//     the body patch that overlaps it (in front of it along the eye's ray in the bottom levels, behind
//     it in the rasterised depth); its ray meets that patch unless the origin clears it: wrong with the
//     chapter's 64 to 256 ulps and with a floor of 1/65536, right with 1024 ulps and with the floor.
//   tests/hard/scenes/occluder_large_coordinates (mid, 384^2, 13512 judged: an aircraft at 1e5): 14.8% /
//     11.9% here, 20.0% / 16.4% with the chapter's 256 ulps (17.6% / 14.6% with 32). What remains is
//     not the offset: the G-buffer, drawn without culling, sees lower skins that the rounded positions
//     lift through the upper ones, where the lighting pass culls them; with --back-faces draw 0.34% /
//     0.07% here and 11.2% / 9.0% with 256 ulps (tests/hard/HardCases.h, its raytraced row).
// Rounding p + d n loses at most half a spacing per coordinate, and moves a coordinate not at all only
// where 32 n_i^2 < 1/2.
const float kOffsetSpacings = 32.0;
const float kOffsetFloor = 1.0e-4;

vec3 offsetRayOrigin(vec3 p, vec3 n) {
    vec3 a = abs(p);
    vec3 spacing = intBitsToFloat(floatBitsToInt(a) + 1) - a;
    return p + max(kOffsetFloor, kOffsetSpacings * dot(abs(n), spacing)) * n;
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
