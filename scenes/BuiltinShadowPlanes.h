#pragma once
// The occluder-texture shadow planes that generated content comes with (Coleman, "Fast Self-Shadowing
// Using Occluder Textures", sections 4.3 and 5): the thesis's choices for its two test models, derived
// from the generated mesh's vertex data (principal axes and extents of its parts), so that they stay
// valid at every tessellation.
//
// aircraft (3 planes, Figure 13):
//   "wings"     the wings' mid-plane (y = 0) through fuselage, wings and stabilisers, parts {fuselage,
//               wings, stabilisers}: the thesis's texture A, the top view without the fins.
//   "fin_right" the right fin's mid-plane, parts {fin_right}, reaching below the fin root down to the
//               wings' plane, inside the fuselage: room for the extension of section 5.
//   "fin_left"  the same for the left fin, texture_of "fin_right" (texture B shared by both fins), its
//               frame the mirror image of fin_right's (z -> -z), so mirrored points get the same uv.
// teapot (11 planes, Figures 16, 18 and 20; the round body, rim and bottom get none):
//   "lid_side", "lid_front" two perpendicular vertical planes through the lid's axis (the knob's), parts
//               {lid}, the same silhouette: lid_front is lid_side turned 90 degrees about the axis and
//               uses its texture (texture_of).
//   "lid_knob"  horizontal, at the knob's widest ring, a square around that ring, parts {lid}.
//   "spout_vertical", "spout_horizontal", "spout_cap" along the spout's principal axis: the vertical
//               profile (the teapot's mirror plane), the horizontal profile (the plane through the axis
//               perpendicular to it) and a cap perpendicular to the axis at the spout's tip, parts {spout}.
//   "handle_1" .. "handle_5" solid (no texture) strips end to end along the handle's C, from the upper
//               joint down, each spanning one fifth of the C's centre curve and the handle's width.
// Receivers (the thesis's receiver sections, ShadowPlane::receivers): "spout_horizontal" and "spout_cap"
// shadow every part but the spout (their silhouettes cover the spout's own lit tip); the others every part.
// Every plane keeps a margin of kMarginFraction of its larger side around what it covers (a white border,
// so the silhouette never reaches the clamped edge texels), except the solid handle strips, whose
// rectangle is the shadow itself.
#include <array>
#include <string>
#include <vector>

#include "scenes/Mesh.h"
#include "scenes/ShadowPlane.h"

namespace sb {

/// Mean and principal axes of a point set: the eigenvectors of its covariance (Jacobi rotations, in
/// double), ordered by decreasing variance (also the automatic chooser's candidate normals).
struct PrincipalAxes {
    glm::vec3 mean{0.0f};
    std::array<glm::vec3, 3> axes{};
    std::array<double, 3> variance{};
};
PrincipalAxes principalAxes(const std::vector<glm::vec3>& points);

struct BuiltinShadowPlanes {
    /// The planes of a mesh made by MeshGenerators' `generator` ("aircraft", "teapot"; none for every
    /// other generator, and none when the mesh lacks the parts they stand for, e.g. a non-standard
    /// teapot patch file). The planes are validated (ShadowPlane::validate).
    static std::vector<ShadowPlane> forGenerator(const std::string& generator, const Mesh& mesh);
    static std::vector<ShadowPlane> aircraft(const Mesh& mesh);
    static std::vector<ShadowPlane> teapot(const Mesh& mesh);

    /// Border around the covered geometry on each side, as a fraction of the larger of its extents
    /// (10 texels of a 256-texel texture, the thesis's resolution).
    static constexpr float kMarginFraction = 0.04f;
    /// The number of solid segments along the teapot's handle (section 5: five gave the best result).
    static constexpr int kHandleSegments = 5;
};

} // namespace sb
