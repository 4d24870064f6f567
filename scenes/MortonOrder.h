#pragma once
// A spatially coherent order for a set of points: sorted along the Morton code (Z-order curve) of each
// point, quantised to 10 bits per axis over the points' own bounds. Points that are near in space get
// codes that share their high bits, so they end up near in the order. The idea is the ordering step of
// Lauterbach et al., "Fast BVH Construction on GPUs" (Eurographics 2009), section 3 (linear BVH: Morton
// codes of the primitives' centroids, sorted).
//
// Used by techniques/raytraced/AccelerationStructures to list the casters in the top level's instance
// buffer: lavapipe's top-level builder keeps the locality of the order it is given (the measurements are
// in that header and in results/raytraced/README.md, "The top level and the order of instances").
#include <cstddef>
#include <cstdint>
#include <vector>

#include "scenes/Mesh.h"

namespace sb {

/// The 30-bit Morton code of `p` in `bounds`: each axis quantised to 10 bits (0 at bounds.min, 1023 at
/// bounds.max, clamped outside), then interleaved, x in the lowest bit of each triple (bit 3i: x's bit i,
/// 3i+1: y's, 3i+2: z's). An axis of zero extent quantises to 0.
uint32_t mortonCode(const glm::vec3& p, const Aabb& bounds);

/// The indices 0..n-1 of `points`, sorted by their Morton codes over the points' bounds; points with equal
/// codes keep their input order (stable). A permutation of 0..n-1.
std::vector<size_t> mortonOrder(const std::vector<glm::vec3>& points);

} // namespace sb
