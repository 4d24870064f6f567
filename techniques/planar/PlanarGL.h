#pragma once
// `planar`: projected planar shadows (Crawfis, "Ad-hoc shadows", "Projected Occluder"; thesis section
// 2.1). Pass "lighting" renders the scene lit and unshadowed. Pass "shadows" then, for every light
// and every receiver plane the scene declares (scenes/ReceiverPlane.h: grounds, walls), flattens the
// casters onto the plane with the slides' 4x4 matrix and removes that light from the receiver where
// they land:
//   stencil=true (the slides' algorithm): the receiver's rectangle marks the stencil where it is
//   visible; the flattened occluders are drawn without depth test where the stencil is set and clear
//   it, so each pixel darkens once (no double blending) and nothing lands off the receiver;
//   stencil=false: the flattened occluders are depth-tested against the receiver with a polygon offset
//   (the slides' "use bias"): overlap darkens twice and shadows run off the receiver's edge.
// "Darken" is exact rather than a grey: the colour target gets albedo * darkness * lightTerm of that
// light subtracted (reverse-subtract blending) and the light's visibility channel multiplied by
// 1 - darkness, so with darkness 1 a shadowed pixel is what every other technique renders.
//
// Guards against the slides' wrong shadows and anti-shadows (property `guards`): a light behind the
// receiver or in its plane (P.L <= 0) casts nothing on it; occluder parts behind the receiver are
// clipped (gl_ClipDistance[0] = P.v); parts as far from the plane as a point light or farther, which
// would project through infinity to the other side, are clipped by handing the rasteriser M v
// undivided (w < 0 lies outside every clip volume) with a margin (gl_ClipDistance[1] = w - 1e-4 P.L).
// guards=false is the slides' per-vertex formula divided out in the vertex shader, with every
// artefact they show.
// `occluder=proxy` flattens each caster's ShadowProxy (sphere, box or cylinder, declared or fitted)
// instead of its mesh: the summary slide's simplified proxy occluder.
//
// What it cannot do (its declared effects leave them out): self-shadowing (casters are receivers of
// nothing), shadows on anything but the declared planes, soft shadows.
#include <vector>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "scenes/InstanceCulling.h"
#include "scenes/ReceiverPlane.h"
#include "techniques/gl/GlTechnique.h"
#include "techniques/gl/MeshBuffers.h"
#include "techniques/gl/ReceiverStencil.h"
#include "techniques/planar/Planar.h"

namespace sb {

class PlanarGL final : public GlTechnique {
public:
    PlanarGL();
    ~PlanarGL() override;
    void setScene(const Scene& scene) override;
    /// The flattening matrices follow the lights; the proxy occluders (occluder=proxy) the casters.
    void sceneChanged(const Scene& scene, uint32_t changes) override;
    void compile(const CompileContext& ctx) override;
    void execute(FrameContext& ctx) override;
    Counters counters() const override { return mCounters; }

    /// One flattening (Planar::Projection). Public for tests.
    using Projection = Planar::Projection;
    static std::vector<Projection> projections(const std::vector<ReceiverPlane>& planes, const Scene& scene,
                                               bool guards) {
        return Planar::projections(planes, scene, guards);
    }

private:
    struct ProxyBatch {
        GLuint vao = 0;
        GLsizei indexCount = 0;
        GLsizei first = 0, count = 0; ///< instance range in mProxyInstances
    };
    void uploadProxies(const Scene& scene);
    void release();
    /// The "shadows" pass: every flattening of a caster onto a receiver plane, per light.
    void renderShadows(FrameContext& ctx);
    /// The counters of the frame just drawn.
    void setCounters(const FrameContext& ctx);
    void drawOccluders(FrameContext& ctx, const Projection& p, InstanceMask keep);
    void setShadowState(bool stencil);

    std::vector<ReceiverPlane> mPlanes;
    std::vector<Projection> mProjections;
    ReceiverStencil mReceivers;
    MeshBuffers mProxyMeshes; ///< unit sphere, box, cylinder (around z)
    GLuint mProxyInstances = 0;
    std::vector<ProxyBatch> mProxyBatches;
    uint64_t mProxyTriangles = 0; ///< per flattening
    bool mStencil = true, mUseProxies = false, mGuards = true, mCull = true;
    InstanceCulling mCulling;   ///< the casters' bounds, for cull
    std::vector<uint8_t> mKeep; ///< the casters one flattening keeps
    size_t mCulled = 0;         ///< casters left out over the frame's flattenings
    float mDarkness = 1.0f;
    const Program* mLitProgram = nullptr;
    const Program* mMarkProgram = nullptr; ///< mReceivers' program
    const Program* mShadowProgram = nullptr;
    const Program* mProxyProgram = nullptr; ///< the shadow program reading instanced attributes
    Counters mCounters;
};

} // namespace sb
