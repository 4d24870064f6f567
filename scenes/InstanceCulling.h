#pragma once
// Per-frustum culling of a scene's instances for the passes that render from a light (each shadow map,
// cube face, paraboloid half or cascade): an instance whose world-space bounding box lies wholly
// outside one plane of the pass's clip volume cannot put a texel into that map, so it is not
// submitted. The test is conservative (a box that straddles a plane's corner region is kept), done on
// the CPU once per pass, and costs 8 corner transforms per instance; what it keeps is the mask
// Submitter::draw takes (techniques/gl/Submitter.h). The same test culls casters whose shadow
// cannot reach the camera's view (cullShadows, cullFlattened): the passes that draw casters for
// the receivers the camera sees (projective's texture, planar's flattening) leave those out.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/DrawSet.h"
#include "scenes/Mesh.h"
#include "scenes/Scene.h"

namespace sb {

/// Which planes of the clip volume cull. A shadow map's casters between the light and the near plane
/// still shadow what lies inside (a cascade is fitted to the receivers it covers, its casters may lie
/// anywhere towards the light), so such passes cull against the side planes and the far plane only
/// and clamp depth instead (GL_DEPTH_CLAMP: "pancaking").
enum class CullPlanes { All, SidesAndFar };

/// What the camera sees, for leaving out casters whose shadow cannot fall there (cullShadows,
/// keepReachingView).
struct ViewReach {
    glm::mat4 camera{1.0f}; ///< the camera's projection * view
    Aabb receivers;         ///< the bounds of what can receive a shadow (empty: unknown, keep all)
};

class InstanceCulling {
public:
    /// Each mesh's model-space bounds (one pass over its vertices), every instance's world-space bounds
    /// and the size of each DrawSet (untimed: at setScene). Keeps a pointer to `scene` for the sets'
    /// membership, as the Submitter's upload does: it must outlive the culls.
    void setScene(const Scene& scene);

    /// Fills `keep` (one entry per instance) with 1 for each instance of `set` whose bounds may reach
    /// the clip volume of `viewProj`, 0 for the rest; returns how many of `set` were kept.
    size_t cull(const glm::mat4& viewProj, DrawSet set, CullPlanes planes, std::vector<uint8_t>& keep) const;
    /// Instances of `set` (the denominator of a culling counter), counted at setScene.
    size_t count(DrawSet set) const { return mSetCount[size_t(set)]; }

    /// The casters (DrawSet::Casters) whose shadow may fall on something the camera sees: the caster's
    /// bounds extruded away from `light` until past `receivers` (the bounds of what can receive), tested
    /// against the camera's `viewProj`. A caster whose shadow lies wholly outside the view is 0 in
    /// `keep`, so a technique that draws casters into a light's texture (projective) leaves it out.
    size_t cullShadows(const Light& light, const Aabb& receivers, const glm::mat4& viewProj,
                       std::vector<uint8_t>& keep) const;
    /// Clears in `keep` (a mask from cull()) the casters whose shadow from `light`, each caster's bounds
    /// grown by `margin` world units on every side (a map filter's footprint), cannot reach
    /// `view`; returns how many stay kept. What a light's map needs for the receivers in view.
    size_t keepReachingView(const Light& light, const ViewReach& view, float margin,
                            std::vector<uint8_t>& keep) const;
    /// The casters whose flattening by `flatten` (a planar projection matrix, homogeneous: planar's
    /// ReceiverPlane::projection) may reach the camera's view `viewProj`. `divided`: the vertex stage
    /// divides the flattened point by its w before projecting (planar without guards), which keeps
    /// hulls convex only where every corner has w > 0, so a caster with one corner beyond the light is
    /// kept.
    size_t cullFlattened(const glm::mat4& flatten, const glm::mat4& viewProj, bool divided,
                         std::vector<uint8_t>& keep) const;
    /// Instances' world bounds follow their model matrices again (a scene in motion moved its casters).
    /// Inside the timed frame, so it transforms the meshes' bounds kept at setScene (8 corners per
    /// instance) instead of reading every vertex again; a scene whose meshes or instances changed in
    /// number is set up again.
    void instancesMoved(const Scene& scene);
    /// World-space bounds per instance (indexed like Scene::instances), as of setScene.
    const std::vector<Aabb>& bounds() const { return mBounds; }

    /// True if the box may reach the clip volume of `viewProj`: not all 8 corners outside one plane.
    static bool mayReach(const Aabb& box, const glm::mat4& viewProj, CullPlanes planes);
    /// Whether the shadow `light` casts from `box` (grown by `margin`), swept past `receivers`, may
    /// reach the clip volume of `viewProj`.
    static bool shadowMayReach(const Aabb& box, const Light& light, const Aabb& receivers,
                               const glm::mat4& viewProj, float margin);
    /// True unless every homogeneous point (world space, or a flattening's output) lies outside one
    /// plane of the clip volume of `viewProj`. Each clip plane is a half-space of homogeneous space, so
    /// then the points' convex hull, and whatever lies inside it, misses the view too.
    static bool hullMayReach(const glm::vec4* points, size_t count, const glm::mat4& viewProj,
                             CullPlanes planes);

private:
    const Scene* mScene = nullptr;
    std::vector<Aabb> mMeshBounds; ///< per mesh, model space (motion moves instances, not vertices)
    std::vector<Aabb> mBounds;     ///< per instance, world space
    std::array<size_t, kDrawSetCount> mSetCount{};
};

} // namespace sb
