#pragma once
// `blob`: fake proxy shadows (Crawfis, "Ad-hoc shadows", "Fake Proxy Shadow": "a simple hand-drawn
// polygon or texture", "e.g. draw the bottom of the bounding box", "the desk with a fake shadow using
// an ellipse"). A soft ellipse on the ground plane under each caster and for each light:
//   - oriented and sized from the caster's world bounds and the light: the eight corners of the bounds
//     are projected onto the ground along the light (from a point light's position, or along a
//     directional light's direction); the ellipse is centred on their mean, its axes are their
//     principal axes (2x2 covariance) and its semi-axes sqrt(2) standard deviations: the ellipse
//     through the corners of a rectangular footprint, and continuous in the light and the object;
//   - a point light within a caster's height (a torch among pillars): the shadow of such a caster is
//     a wedge behind it that runs off to infinity, so corners that would land beyond where the light
//     reaches on the ground (its range's circle, the ground's rectangle) are held there, in their
//     direction from the light: the blob covers the wedge as far as anything is lit, behind the
//     caster, instead of the whole pool; a caster wholly beyond the range gets no blob;
//   - opacity falls with the height of the bounds' bottom over the ground, linearly to 0 at `fade`
//     bounding radii;
//   - a radial profile 1 - smoothstep(1 - softness, 1, r) (r = 1 on the ellipse): the fake softness.
// Pass "lighting" renders the scene lit and unshadowed; pass "blobs" fits every blob on the CPU (what
// a game does per frame for moving objects), uploads them, marks the ground's rectangle in the stencil
// (scenes/ReceiverPlane.h) and draws all blobs in one instanced draw of quads, removing each light's
// term from the ground's colour and scaling its visibility channel by 1 - alpha, as `planar` does.
// Overlapping blobs multiply (each darkens again): the look of the trick.
//
// The ground plane is the receiver plane whose normal points most nearly up (+y, at least 60 degrees
// above the horizon). What it cannot do: self-shadowing, shadows on anything but the ground, shadows of
// the right shape (a box, a wing and a sphere all get an ellipse), hard shadows.
#include <optional>
#include <vector>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "scenes/ReceiverPlane.h"
#include "techniques/blob/Blob.h"
#include "techniques/gl/GlTechnique.h"
#include "techniques/gl/ReceiverStencil.h"

namespace sb {

class BlobGL final : public GlTechnique {
public:
    BlobGL();
    ~BlobGL() override;
    void setScene(const Scene& scene) override;
    /// Blobs are fitted to the casters and lights in every frame; the ground does not move.
    void sceneChanged(const Scene&, uint32_t) override {}
    void compile(const CompileContext& ctx) override;
    void execute(FrameContext& ctx) override;
    Counters counters() const override { return mCounters; }

    /// A blob record (Blob::Record). Public for tests.
    using Blob = sb::Blob::Record;
    static std::optional<Blob> fit(const Aabb& bounds, const ReceiverPlane& ground, const Light& light,
                                   int lightIndex, float opacity, float softness, float fade) {
        return sb::Blob::fit(bounds, ground, light, lightIndex, opacity, softness, fade);
    }
    static std::optional<ReceiverPlane> findGround(const Scene& scene) { return sb::Blob::findGround(scene); }

private:
    void fitAll(const Scene& scene);
    void release();

    std::optional<ReceiverPlane> mGround;
    std::vector<Aabb> mMeshBounds; ///< object space, per mesh
    std::vector<Blob> mBlobs;      ///< this frame's
    GLuint mBlobBuffer = 0, mEmptyVao = 0;
    size_t mCapacity = 0;
    ReceiverStencil mReceiver;
    const Program* mLitProgram = nullptr;
    const Program* mBlobProgram = nullptr;
    Counters mCounters;
};

} // namespace sb
