#pragma once
// Procedural meshes for the built-in content (DESIGN.md section 8). Each has a tessellation knob:
// the vertex-load knob of the bottleneck studies (doubling it roughly quadruples the triangles of the
// curved parts). All are closed, consistently wound (counter-clockwise outward) meshes with smooth or
// faceted normals as noted, except the ground plane (a single-sided grid) and the teapot (the original
// patches leave the bottom and the lid/body seam open, as every Utah teapot does).
#include <string>

#include "scenes/Mesh.h"

namespace sb {

struct MeshGenerators {
    /// Unit sphere (radius 1) from `tess` rings and 2*tess segments. tess >= 3.
    static Mesh sphere(int tess);
    /// Axis-aligned box with half extents `halfExtent`, each face split tess x tess, faceted normals.
    static Mesh box(glm::vec3 halfExtent, int tess);
    /// Closed cylinder along +Y, radius 1, height 2 (y in [-1,1]), 2*tess segments, capped.
    static Mesh cylinder(int tess);
    /// Ground plane at y = 0 facing +Y, size x size, split tess x tess.
    static Mesh plane(float size, int tess);
    /// The F-35-role aircraft (thesis Figures 3-5, 13): fuselage along +X (nose at +X), planar wings and
    /// horizontal stabilisers in the y = 0 plane, two canted tail fins. Length ~ 2 units.
    /// Parts: "fuselage", "wings", "stabilisers", "fin_left", "fin_right".
    static Mesh aircraft(int tess);
    /// Utah teapot from the Bezier patch file (teapot.bpt format), each patch tessellated into
    /// tess x tess quads. Parts: "rim", "body", "lid", "handle", "spout" (patch groups of the data).
    static Mesh teapot(const std::string& bptPath, int tess);
};

} // namespace sb
