#pragma once
// Automatic choice of shadow planes for an arbitrary mesh (a --model file): the thesis's future work,
// "methods for automated choice of cut-planes for the shadow planes" (Coleman, "Fast Self-Shadowing
// Using Occluder Textures", section 7); the occluder textures are then baked from the mesh as for
// every plane (texture "auto").
//
// The thesis's modeller picks planes that cut the object where a flat stand-in captures its shadow-
// casting geometry (sections 4.3 and 5), and a plane shadows only receivers on its far side from the
// light (s_I > 0, section 4.1). The chooser does the same by measurement, on the CPU, before anything is
// drawn:
//  - candidates: planes through the mesh perpendicular to its three principal axes (the thesis's aircraft
//    planes are its principal mid-planes) and to each light direction given (the plane the shadow is
//    cast through, seen from the light), each at ten offsets (the 20/35/50/65/80% quantiles of the
//    vertices along the normal, and the same fractions of the mesh's extent along it), the rectangle
//    covering the mesh's projection; each in two texture
//    modes, the plane's cross-section with the solid alone (section_only: safe, a ray through it runs
//    through the solid) and the mesh's orthographic silhouette with it (what the bake does by default:
//    more shadow, but a ray through the silhouette may pass beside the mesh, a false shadow);
//  - the score: surface samples (triangle centroids, weighted by area) lit by each light direction
//    (n.L > 0.05, what the accuracy judge counts), widened to a 10-degree cone of directions, each
//    classified exactly by a ray cast against the mesh (a BVH); a candidate's gain is the sample weight
//    it newly shadows correctly minus three times the weight it shadows falsely (a false shadow is
//    worse than none: it darkens a lit surface; three rather than two measured fewer wrong pixels on
//    glmark2's horse under a high light), using the same test as the shader (s_I > 0, uv in [0, 1]^2, the
//    texel black);
//  - greedy: the best candidate is kept while its gain exceeds kMinGain of the judged weight, up to
//    maxPlanes, each later one scored on what the earlier ones leave.
// Receivers: each chosen plane shadows what lies on its far side from the light (s_I > 0, the thesis's
// rule against false shadows, tested per fragment), on every part (ShadowPlane::receivers empty): a
// model's parts are whatever its file grouped, not sections cut for its shadows, and the score already
// counts the false shadow a plane casts on its far side.
// Cost: untimed setup, about 1 s for a 70k-triangle model and one light direction, 3.6 s for eight (the
// bunny under a 200-instance layout, llvmpipe machine, 2 cores).
// A mesh none of whose candidates gains enough (a convex one casts no shadow on itself; a model whose
// shadows no flat stand-in captures) gets no plane, and the choice says why in one line (`reason`).
//
// Without light directions the set is the 14 directions of the cube's faces and corners (light-
// independent, as the thesis's planes are); with them the planes are chosen for those lights (a light
// moved far from them keeps the planes valid, s_I tested, but not necessarily useful).
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/Mesh.h"
#include "scenes/ShadowPlane.h"

namespace sb {

struct ShadowPlaneChoice {
    std::vector<ShadowPlane> planes; ///< validated, texture "auto"; empty when none is useful
    std::string reason;              ///< empty when planes were chosen, else why none, one line
    double judgedWeight = 0.0;       ///< lit sample weight (area x directions)
    double shadowedPct = 0.0;        ///< of it, % truly in shadow (the ray cast)
    double capturedPct = 0.0;        ///< % the chosen planes shadow correctly
    double falsePct = 0.0;           ///< % they shadow falsely
};

struct ShadowPlaneChooser {
    /// Chooses up to `maxPlanes` planes for `mesh` (object space) and the unit directions towards the
    /// light in object space (empty: the 14 default directions). Deterministic.
    static ShadowPlaneChoice choose(const Mesh& mesh, const std::vector<glm::vec3>& towardLight,
                                    int maxPlanes = 4);

    /// A candidate must gain at least this share of the judged weight (0.2%) to be kept.
    static constexpr double kMinGain = 0.002;
    /// Texels per side of the CPU occluder textures the score uses.
    static constexpr int kResolution = 128;
};

} // namespace sb
