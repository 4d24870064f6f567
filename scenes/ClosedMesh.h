#pragma once
// Whether a mesh is closed: the fact that lets a pass cull its back faces without changing the image.
// Seen from outside, the nearest surface of a closed, outward-wound mesh along any ray is a front face
// (the ray enters the volume there), so dropping the back faces changes neither a depth map nor a lit
// image (scenes/BackFaceCulling.h says when a pass's viewpoint is "outside").
#include <cstddef>

#include "scenes/Mesh.h"

namespace sb {

struct ClosedMeshReport {
    /// Directed edges (a, b) of the welded mesh not matched by as many (b, a): a boundary (a hole or
    /// an open edge) or a winding that flips between neighbours. 0 for an oriented closed surface.
    size_t unmatchedEdges = 0;
    size_t components = 0;       ///< connected components (by shared welded vertices) with a triangle
    size_t inwardComponents = 0; ///< of those, the ones enclosing zero or negative signed volume
    bool closed() const { return components > 0 && unmatchedEdges == 0 && inwardComponents == 0; }
};

/// Computes the closedness of `mesh` (untimed: at load). Vertices with bit-identical positions are
/// welded first (a box with split vertices per face is one surface; -0 welds with +0); degenerate triangles
/// (two equal welded corners) are ignored. Closed: every directed edge (a, b) is matched by as many (b, a),
/// and every connected component encloses positive signed volume (counter-clockwise front faces wind outward;
/// an inside-out component is not closed). A mesh without triangles is not closed.
ClosedMeshReport computeClosedness(const Mesh& mesh);

/// computeClosedness(mesh).closed().
bool isClosedMesh(const Mesh& mesh);

} // namespace sb
