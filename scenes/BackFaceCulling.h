#pragma once
// When a pass may cull the back faces of an instance without changing what it renders. Seen from a
// point outside a closed, outward-wound mesh (scenes/ClosedMesh.h), the first surface along every ray is
// a front face, so without the back faces neither the depth a shadow map keeps nor the colour a lit
// pass keeps changes. The rule asks three things of the pass and the instance's world bounds:
//  - the projection is linear (a matrix: perspective, ortho, cube faces, cascades); a vertex-stage
//    warp (paraboloid) or a flattening onto a plane (planar's casters) is not;
//  - a perspective projection's centre lies outside the bounds (the camera is not inside the mesh);
//  - unless the pass clamps depth (the shadow maps' pancaking, scenes/InstanceCulling.h), every corner
//    of the bounds lies in front of the near plane: a near plane that cuts a closed mesh opens it, and
//    the inside (back faces) shows through the cut.
// Which window winding is front depends on the pass's matrix (a negative determinant mirrors) and on the
// API's framebuffer (Vulkan's y runs down, GL's up): frontFaceCounterClockwise.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/InstanceCulling.h"
#include "scenes/Mesh.h"
#include "scenes/Scene.h"

namespace sb {

/// Whether the pass's run option allows culling at all (`--back-faces cull|draw`).
enum class BackFaces { Cull, Draw };
/// "cull" or "draw": the option's value, the CSV column `back_faces`.
const char* backFacesName(BackFaces mode);
/// The mode named `text`, or nothing for another word.
std::optional<BackFaces> parseBackFaces(const std::string& text);

/// A pass's view for the rule, as the submitters take it (techniques/gl/Submitter.h,
/// techniques/vulkan/VulkanSubmitter.h).
struct CullView {
    glm::mat4 viewProj{1.0f}; ///< world -> clip space, GL's conventions (clip z in [-w, w])
    bool clampsDepth = false; ///< GL_DEPTH_CLAMP / depthClampEnable: the near plane does not cut
};

/// True if the back faces of an instance with world bounds `box` may be culled in the pass `view`
/// (the instance's mesh must be closed: the caller checks Mesh::closed first). Costs at most 8 corner
/// transforms. False for an empty box.
bool mayCullBackFaces(const Aabb& box, const CullView& view);
/// The same with the view's projection centre given (projectionCentre; nullptr: a parallel
/// projection), so that a pass over many instances finds it once.
bool mayCullBackFaces(const Aabb& box, const CullView& view, const glm::vec3* centre);

/// The projection centre of `viewProj` in world space: the point whose clip x, y and w are 0. Returns
/// false for a parallel projection (the centre lies at infinity).
bool projectionCentre(const glm::mat4& viewProj, glm::vec3& centre);

/// Whether Mesh's front faces (counter-clockwise seen from outside) are counter-clockwise in the pass's
/// framebuffer as the API counts winding: true unless `viewProj` mirrors (a cube face may; a GL
/// projection's z flip does not count) xor `framebufferYDown` (Vulkan, whose projections here flip y
/// so the image matches GL's).
bool frontFaceCounterClockwise(const glm::mat4& viewProj, bool framebufferYDown);

/// The per-instance decisions of one pass, shared by the GL and Vulkan submitters: which instances the
/// current pass draws with back faces culled. Candidates (at setScene, again when instances move): instances
/// of closed meshes whose model matrix does not mirror (a mirroring model turns its front faces clockwise).
/// setView (inside the timed frame) tests only the candidates, 8 corner transforms each.
class BackFaceCuller {
public:
    /// `mode` Draw: nothing is ever culled (setView leaves every decision 0).
    void setScene(const Scene& scene, BackFaces mode);
    /// Instances' world bounds and mirroring follow their model matrices again (a scene in motion
    /// moved them): inside the timed frame, so no vertex is read (InstanceCulling::instancesMoved).
    void instancesMoved(const Scene& scene);
    /// Decides every instance for the pass `view`; nullptr: a pass that never culls (a warp, a
    /// flattening, shadow volumes, anything not on the linear path). Returns how many are culled.
    size_t setView(const CullView* view, bool framebufferYDown);
    /// 1 for an instance drawn with back faces culled in the current view; empty when none is.
    const std::vector<uint8_t>& decisions() const { return mCulled; }
    bool culls(size_t instance) const { return mAny && mCulled[instance]; }
    bool any() const { return mAny; }
    /// The front winding of the current view (frontFaceCounterClockwise).
    bool frontCounterClockwise() const { return mFrontCcw; }

private:
    /// The instances of mClosed whose model matrix does not mirror, into mCandidates.
    void findCandidates(const Scene& scene);

    BackFaces mMode = BackFaces::Cull;
    InstanceCulling mBounds;           ///< world bounds per instance
    std::vector<uint32_t> mClosed;     ///< instances of closed meshes (the mesh never changes)
    std::vector<uint32_t> mCandidates; ///< of mClosed, those whose model does not mirror
    std::vector<uint8_t> mCulled;
    bool mAny = false;
    bool mFrontCcw = true;
};

} // namespace sb
