#pragma once
// `occluder`: single-pass self-shadowing from shadow planes with occluder textures (Coleman, "Fast
// Self-Shadowing Using Occluder Textures", sections 4-5 and Appendices A-B).
//
// Every mesh may carry shadow planes (scenes/ShadowPlane.h: declared in the scene file or built in for
// the aircraft and the teapot). One pass draws the scene: the vertex stage projects each vertex onto
// its mesh's planes along the light (equations 6 and 8) and the fragment stage multiplies the occluder
// texture values where s_I > 0 (shaders/occluder/). An instance is shadowed only by its own mesh's
// planes, which is the thesis's technique: self-shadowing; receivers without planes (the ground) get no
// shadow, and the accuracy numbers count that.
//
// A plane may name the mesh parts that receive it (the thesis's receiver sections, ReceiverSections.h);
// a mesh without given planes (a --model file, Mesh::shadowPlanesAuto) gets up to kAutoPlanes chosen for
// the scene's lights in setScene (scenes/ShadowPlaneChooser.h), or none, said on stderr and counted in
// the counter no_useful_planes.
//
// Occluder textures are baked from the plane's mesh parts (OccluderTextures: the thesis's future work,
// automated) at `resolution`, or read from the image the scene names, and kept as layers of one
// texture array so a draw needs no per-mesh binding. Plane data and per-instance records live in two
// storage buffers indexed by plane and by instance (object id - 1).
//
// Properties: light_space per_vertex (every vertex transforms the light into model space, the
// thesis's shader), per_instance (the thesis's proposed optimisation: once per instance on the CPU,
// read by the shader from the instance record) or texture_matrix (its future work: for directional
// lights equations 6 and 8 folded on the CPU into one 3x4 matrix per instance and plane, three dot
// products per plane in the vertex stage); planes (use only the first N planes of each mesh, to
// sweep the cost per plane); receivers (self, the thesis; all: every receiver also tests the planes of
// the other instances that may shadow it, per fragment in world space); resolution (baked texture size);
// dilate (texels the baked silhouette is grown by, thesis section 5).
#include <epoxy/gl.h>

#include "techniques/gl/GlTechnique.h"
#include "techniques/occluder/Occluder.h"
#include "techniques/occluder/OccluderPlan.h"

namespace sb {

class OccluderGL final : public GlTechnique {
public:
    OccluderGL();
    ~OccluderGL() override;
    void setScene(const Scene& scene) override;
    /// The planes and their textures stay (an artist's, made once); the light in each instance's space
    /// is found every frame anyway. Moving casters change their inverse transforms, and with
    /// receivers=all the world planes and the caster candidates of every receiver (which also follow
    /// the lights).
    void sceneChanged(const Scene& scene, uint32_t changes) override;
    void compile(const CompileContext& ctx) override;
    void execute(FrameContext& ctx) override;
    Counters counters() const override { return mCounters; }
    /// Most planes chosen automatically for a mesh without given ones (the cost is per plane).
    static constexpr int kAutoPlanes = OccluderPlan::kAutoPlanes;

private:
    void buildTextures(const CompileContext& ctx);
    void uploadInstances();
    void uploadWorldPlanes();
    void release();

    OccluderPlan mPlan; ///< planes, layers, records, permutation, counters (shared with OccluderVulkan)
    size_t mWorldPlanes = 0;
    GLuint mTextures = 0, mPlaneBuffer = 0, mInstanceBuffer = 0, mMatrixBuffer = 0, mWorldPlaneBuffer = 0,
           mCandidateBuffer = 0, mSectionBuffer = 0;
    int mResolution = 0, mLayers = 0;
    const Program* mProgram = nullptr;
    Counters mCounters;
};

} // namespace sb
