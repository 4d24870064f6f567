#pragma once
// Procedural meshes for the built-in content (docs/ARCHITECTURE.md, "Scenes"). Each has a tessellation knob:
// the vertex-load knob of the bottleneck studies (doubling it roughly quadruples the triangles of the
// curved parts). All are closed, consistently wound (counter-clockwise outward) meshes with smooth or
// faceted normals as noted, except the ground plane (a single-sided grid) and the teapot (the original
// patches leave the lid/body seam and the handle/spout joints open, as every Utah teapot does). The
// lantern is closed too, but not a sphere topologically: a shell with four tunnels, genus 3.
// Tessellation below a generator's minimum (or above 4096) throws sb::Error.
#include <string>

#include "scenes/Mesh.h"

namespace sb {

struct MeshGenerators {
    /// Unit sphere (radius 1) from `tess` rings and 2*tess segments. tess >= 3.
    static Mesh sphere(int tess);
    /// Axis-aligned box with half extents `halfExtent`, each face split tess x tess, faceted normals.
    static Mesh box(glm::vec3 halfExtent, int tess);
    /// Closed cylinder along +Y, radius 1, height 2 (y in [-1,1]), 2*tess segments, tess rows, capped
    /// by triangle fans. tess >= 2.
    static Mesh cylinder(int tess);
    /// Ground plane at y = 0 facing +Y, size x size, split tess x tess.
    static Mesh plane(float size, int tess);
    /// The F-35-role aircraft (thesis Figures 3-5, 13): fuselage along +X (nose at +X), planar wings and
    /// horizontal stabilisers in the y = 0 plane, two canted tail fins. Length ~ 2 units.
    /// Parts: "fuselage", "wings", "stabilisers", "fin_left", "fin_right" (left = -Z: facing +X with +Y
    /// up, +Z is the pilot's right). Fuselage: 2*tess rings x 2*tess segments; the flat parts are
    /// closed slabs 0.02 x wingspan thick, subdivided max(1, tess/4). tess >= 2. 2624 triangles at 16.
    static Mesh aircraft(int tess);
    /// Utah teapot from the Bezier patch file (teapot.bpt format), each patch tessellated into
    /// tess x tess quads, converted from the data's Z-up to Y-up, standing on y = 0 (height 3.15).
    /// Patch p owns the (tess+1)^2 consecutive vertices from p*(tess+1)^2 (row-major), nothing welded.
    /// Parts, in the data's patch order of the standard 32-patch file: "rim" (0-3), "body" (4-11),
    /// "handle" (12-15), "spout" (16-19), "lid" (20-27), "bottom" (28-31); another patch count gives
    /// one part "patches".
    static Mesh teapot(const std::string& bptPath, int tess);
    /// The jack-o'-lantern of GPU Gems chapter 9, Figure 9-2 (the shadow volumes' hard case of a point
    /// light inside a caster): a thick spherical shell, outer radius 1, inner radius 1 - thickness
    /// (0 < thickness < 1), on the grid of sphere(tess) (tess rings, 2*tess segments) with four holes
    /// cut through it: two triangular eyes (apex up, 8..34 degrees above the equator, centred 30
    /// degrees either side of +Z), a wide half-ellipse mouth (12..40 degrees below the equator, +-48
    /// degrees around +Z) and a round hole around the bottom pole (the 28 degrees around -Y). A hole
    /// is the set of grid cells whose centres fall in its outline (made 4-connected row by row), cut
    /// from both spheres; its tunnel wall joins the two cut borders by planar radial quads. Closed and
    /// consistently wound (the inner sphere faces the centre, out of the solid shell); with the four
    /// tunnels V - E + F = 4 - 2*4 = -4 after welding, genus 3. Smooth normals on the spheres,
    /// faceted on the tunnel walls (own vertices). Parts "shell" (outer sphere triangles, then inner)
    /// and "holes" (the tunnel walls). tess >= 8 (each hole at least one cell, no two holes sharing a
    /// vertex; checked, an sb::Error otherwise). 1780 triangles at 16, 6692 at 32, 15160 at 48.
    static Mesh lantern(float thickness, int tess);
    /// The smallest tessellation each generator accepts (the table of scenes/MeshGeneratorTable.h
    /// lists them beside the generators' names).
    static constexpr int kSphereMinimumTessellation = 3;
    static constexpr int kBoxMinimumTessellation = 1;
    static constexpr int kCylinderMinimumTessellation = 2;
    static constexpr int kPlaneMinimumTessellation = 1;
    static constexpr int kAircraftMinimumTessellation = 2;
    static constexpr int kTeapotMinimumTessellation = 1;
    static constexpr int kLanternMinimumTessellation = 8;
};

} // namespace sb
