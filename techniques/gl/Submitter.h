#pragma once
// Submission is orthogonal to technique (docs/ARCHITECTURE.md, "Submission"): techniques never loop over
// scene draws, they ask a Submitter to draw a set of instances with the program they have bound. The four
// modes are the four ways an application of each era fed geometry to GL, so the CPU cost of submission can be
// varied without touching the technique:
//   immediate   glBegin/glEnd with generic attributes, per-instance uniforms (the thesis's CPU-bound case)
//   displaylist one display list per mesh, compiled at upload (the thesis's retained path)
//   retained    one VAO (VBO+IBO) per mesh, one glDrawElements per instance
//   instanced   one glDrawElementsInstanced per mesh and instance set, per-instance attributes
// Vertex attributes: location 0 position, 1 normal. Per-instance data: uniforms at location 0 (mat4
// model) and 4 (vec4 colour rgb + object id) or, instanced, attributes 4..7 and 8. Shaders include
// shaders/common/instance.glsl, which reads either form depending on the SB_INSTANCED define.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "gl/ProgramCache.h"
#include "scenes/BackFaceCulling.h"
#include "scenes/DrawSet.h"
#include "scenes/Scene.h"
#include "techniques/Submission.h"

namespace sb {

class Submitter {
public:
    virtual ~Submitter() = default;
    static std::unique_ptr<Submitter> create(SubmitMode mode);

    virtual SubmitMode mode() const = 0;
    /// Untimed preparation for a scene: buffers, display lists, instance buffers, draw orders, and the
    /// back-face candidates (scenes/BackFaceCulling.h). Must be called with a current context; may be
    /// called again for a new scene.
    void upload(const Scene& scene) {
        mBackFaceCuller.setScene(scene, mBackFaces);
        uploadMode(scene);
    }
    /// A scene in motion moved instances (their model matrices): modes that keep per-instance data on
    /// the GPU (instanced) upload it again; the others read it at each draw. Inside the timed frame.
    void instancesMoved(const Scene& scene) {
        mBackFaceCuller.instancesMoved(scene);
        instancesMovedMode(scene);
    }
    /// The run's --back-faces (scenes/BackFaceCulling.h), before upload: Draw never culls.
    void setBackFaces(BackFaces mode) { mBackFaces = mode; }
    /// The view of the pass that draws next, for back-face culling: each instance of a closed mesh that
    /// view cannot see inside (mayCullBackFaces) is drawn with GL_CULL_FACE on and glFrontFace set for
    /// the view's handedness. nullptr (the default; what BackFaceScope restores): both faces, for
    /// passes off the linear path (a paraboloid warp, planar's flattening, shadow volumes). Inside the
    /// timed frame: 8 corner transforms per instance of a closed mesh. Leaves GL_CULL_FACE off.
    void setCullView(const CullView* view);
    /// draw(set, keep) under `view` (setCullView), then none again: a pass with one draw.
    void drawCulled(DrawSet set, const CullView& view, InstanceMask keep = {}) {
        setCullView(&view);
        draw(set, keep);
        setCullView(nullptr);
    }
    /// Instances the current view draws culled (the last setCullView's count).
    size_t backFaceCulledInstances() const { return mBackFaceCulled; }
    /// Draws every instance of `set` with the currently bound program.
    void draw(DrawSet set) { draw(set, InstanceMask{}); }
    /// Draws the instances of `set` that `keep` keeps. Culled instances cost no GL call; instanced
    /// mode draws each run of consecutive kept instances of a mesh with one call. Inside a view scope
    /// (setViewScope) only the scope's instances are drawn.
    void draw(DrawSet set, InstanceMask keep) {
        if (mScope.empty())
            drawKept(set, keep);
        else
            drawKept(set, narrowToScope(keep));
        setCullFace(false); // what the technique draws next itself sees both faces
    }
    /// Restricts every draw to the instances `scope` keeps (indexed like Scene::instances) until it is
    /// cleared with an empty mask. A hybrid technique (techniques/hybrid/) sets it while one of its
    /// parts draws the visible scene, so each instance is shaded once, by the part that owns it; the
    /// parts' shadow passes run unscoped. The mask must outlive the scope. Empty: no scope (the normal
    /// path pays one emptiness test per draw call of a technique, not per instance).
    void setViewScope(InstanceMask scope) { mScope = scope; }
    InstanceMask viewScope() const { return mScope; }
    /// Defines the vertex stage needs for this mode (SB_INSTANCED for instanced).
    virtual Defines defines() const { return {}; }

    /// Since the last resetStats() (techniques reset at the start of a frame or pass).
    const SubmitStats& stats() const { return mStats; }
    void resetStats() {
        mLifetime += mStats;
        mStats = {};
    }
    /// Everything since creation, unaffected by resets: the harness's census takes differences of it,
    /// so a technique that resets between its passes cannot hide a pass's draws.
    SubmitStats lifetimeStats() const { return mLifetime + mStats; }

protected:
    virtual void uploadMode(const Scene& scene) = 0;
    virtual void instancesMovedMode(const Scene&) {}
    /// The mode's draw of the instances of `set` that `keep` keeps (empty: all of them).
    virtual void drawKept(DrawSet set, InstanceMask keep) = 0;
    /// GL_CULL_FACE as the current view decides for `instance` (a GL call only on a change).
    void cullFor(size_t instance) { setCullFace(mBackFaceCuller.culls(instance)); }
    void setCullFace(bool on);
    const BackFaceCuller& backFaceCuller() const { return mBackFaceCuller; }
    /// Sets the per-instance uniforms (locations 0 and 4) of the bound program.
    static void setInstanceUniforms(const Instance& inst);
    /// glBegin/glEnd stream of a mesh, one glVertexAttrib call per attribute and vertex (normal, then
    /// position: attribute 0 provokes the vertex). Drawn per frame (immediate) or compiled (display lists).
    static void emitImmediate(const Mesh& mesh);
    /// GL calls of emitImmediate(mesh): glBegin, two attributes per index, glEnd.
    static uint64_t immediateCalls(const Mesh& mesh) { return 2 + 2 * uint64_t(mesh.indices.size()); }
    static constexpr uint64_t kInstanceUniformCalls = 2; ///< setInstanceUniforms
    SubmitStats mStats;

private:
    /// `keep` and the view scope, combined in mScoped.
    InstanceMask narrowToScope(InstanceMask keep);
    SubmitStats mLifetime;
    InstanceMask mScope;
    std::vector<uint8_t> mScoped;
    BackFaces mBackFaces = BackFaces::Cull;
    BackFaceCuller mBackFaceCuller;
    size_t mBackFaceCulled = 0;
    bool mCullFaceOn = false;     ///< GL_CULL_FACE as this submitter last set it
    bool mFrontClockwise = false; ///< glFrontFace(GL_CW) set by this submitter (GL_CCW otherwise)
};

/// Sets a pass's cull view (Submitter::setCullView) for the scope's lifetime and restores none (both
/// faces, GL_CULL_FACE off) at its end.
class BackFaceScope {
public:
    BackFaceScope(Submitter& submitter, const CullView& view) : mSubmitter(submitter) {
        mSubmitter.setCullView(&view);
    }
    ~BackFaceScope() { mSubmitter.setCullView(nullptr); }
    BackFaceScope(const BackFaceScope&) = delete;
    BackFaceScope& operator=(const BackFaceScope&) = delete;

private:
    Submitter& mSubmitter;
};

} // namespace sb
