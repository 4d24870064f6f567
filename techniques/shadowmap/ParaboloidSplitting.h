#pragma once
// Which casters of a paraboloid half need their triangles split before the projection
// (shaders/shadowmap/paraboloid_split.geom), decided per caster on the CPU once per hemisphere pass.
//
// The paraboloid projection maps a straight edge to a circular arc of radius at least 1 map unit
// (it is the stereographic projection: great circles go to circles through antipodal points of the
// rim), and a map unit spans at most one radian (at the rim). An edge that spans `a` radians seen
// from the light is drawn as a chord whose sagitta is at most a^2 / 8 map units, a^2 * resolution / 16
// texels. Edges within maxSegmentAngle(resolution) stay within kMaxSagittaTexels of their arc and need
// no split: the plain per-vertex stage (paraboloid_depth.vert) draws them. A caster's widest edge is
// bounded without looking at its triangles: its mesh's longest edge, times the instance's largest
// scale, seen from the nearest point of its world bounds, subtends at most 2 atan(L / 2d); a light
// inside the bounds (d = 0) splits it. Conservative: a caster kept plain is one whose every edge is
// within the angle; a split one may turn out to need n = 1 (the geometry stage then emits it as is).
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/Mesh.h"
#include "scenes/Scene.h"

namespace sb {

class ParaboloidSplitting {
public:
    /// Half a texel: a chord's error stays below the map's own staircase.
    static constexpr float kMaxSagittaTexels = 0.5f;

    /// The widest angle (radians) a segment may span seen from the light in a map of `resolution`^2
    /// texels per half: sqrt(16 kMaxSagittaTexels / resolution) (2048: 0.0625 rad, 3.6 degrees).
    static float maxSegmentAngle(int resolution);

    /// Per instance: world bounds, the longest world edge (its mesh's longest edge times the largest
    /// column length of its model matrix, exact for translate-rotate-scale instances) and whether it
    /// casts. The meshes' longest edges are computed once per mesh count (they do not move).
    void setScene(const Scene& scene);

    /// Splits `keep` (a hemisphere's casters, Submitter::draw's mask) into `plain` (every edge within
    /// `maxAngle` seen from `light`) and `split` (the others); returns how many are split.
    size_t partition(const glm::vec3& light, float maxAngle, const std::vector<uint8_t>& keep,
                     std::vector<uint8_t>& plain, std::vector<uint8_t>& split) const;

    /// The bound on the angle (radians) any edge of instance `i` spans seen from `light`.
    float widestEdgeAngle(size_t i, const glm::vec3& light) const;

private:
    std::vector<float> mMeshLongestEdge;
    std::vector<Aabb> mBounds;
    std::vector<float> mLongestEdge;
};

} // namespace sb
