#pragma once
// Caster culling for the passes of an omnidirectional shadow map, where the pass's volume is not one
// frustum: the layered cube pass covers all six faces at once (their union is the cube of half-size
// far around the light, cut down to the range sphere when the light has a range), and a paraboloid
// half covers a hemisphere of that sphere (Brabec et al. 2002, section 3). A caster whose world bounds
// lie wholly outside the sphere, or wholly behind the hemisphere's plane, cannot put a texel into the
// map, so it is not submitted. Per-frustum culling (one cube face) is scenes/
// InstanceCulling's; the cube's six-pass mode combines both masks. Conservative (a box is tested, not
// the mesh), on the CPU, once per pass; what it keeps is the mask Submitter::draw takes.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/Mesh.h"
#include "scenes/Scene.h"

namespace sb {

class OmniCulling {
public:
    /// World-space bounds of every instance and which cast (untimed: at setScene).
    void setScene(const Scene& scene);

    /// keep[i] = 1 for each caster whose bounds come within `radius` of `centre`, 0 for every other
    /// instance; returns how many were kept.
    size_t cullSphere(const glm::vec3& centre, float radius, std::vector<uint8_t>& keep) const;
    /// As cullSphere, and also 0 for a caster wholly behind the plane through `centre` with normal
    /// `axis` (every corner of its box has dot(corner - centre, axis) < 0): a paraboloid half.
    size_t cullHemisphere(const glm::vec3& centre, float radius, const glm::vec3& axis,
                          std::vector<uint8_t>& keep) const;
    /// Casters in the scene (the denominator of casters_culled).
    size_t casters() const { return mCasters; }

private:
    std::vector<Aabb> mBounds;
    std::vector<uint8_t> mCasts;
    size_t mCasters = 0;
};

} // namespace sb
