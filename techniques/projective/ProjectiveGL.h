#pragma once
// `projective`: projective texture shadows (the ad-hoc technique of the Crawfis slides, "Projective
// Texture Shadows"; the thesis section 2.3). Two passes per frame and light, plus an optional blur:
//   "texture"  per light a light camera (the projector) that encloses the casters' bounds; the casters
//              are drawn black on white into one layer of an R8 texture array (a silhouette: no depth
//              test, no depth at all);
//   "blur"     an optional separable Gaussian (sigma = blur / 2, truncated at `blur` texels) of each
//              layer: the slides' "blur the texture for a fake effect" (it does not model a penumbra;
//              the pass exists at blur 0 but does no GL work);
//   "lighting" the casters drawn fully lit; the non-casting instances (DrawSet::NonCasters: grounds,
//              walls) drawn with the textures projected onto them: visibility_i = the texture of light i
//              at projector_i * world, with projective texture coordinates (s/q, t/q).
// Projectors: directional lights use the shadow map's fit (scenes/LightFit.h: orthographic, fitted to the
// casters' bounds); point and spot lights get a perspective projector at the light, looking at the centre of
// the casters' bounding sphere, with a square frustum whose half-angle encloses that sphere (asin(r / dist),
// padded), near = max(dist - r, 1e-3 dist), far = dist + r (the slides' "light camera that encloses shadowed
// area (bounding box of the occluder)"). A light inside that sphere cannot enclose casters that lie all
// around it (a torch among pillars, a candle in a lantern); there the projector encloses the shadowed area
// itself: it looks from the light at the receivers' bounds (within the light's range), half-angle to their
// farthest corner, far at their deepest corner, near 1e-3 far, so the casters between the light and the
// receivers, the only ones that can shadow them, are in the texture and those above the light are clipped.
// The light among the receivers too looks down the spot's axis, or straight down. A half-angle past
// kMaxHalfAngleDeg = 80 degrees is clamped to it: receivers outside the frustum are lit (the slides'
// "occluder very close to the light: wide frustum" problem, made finite instead of degenerate; in
// jack_o_lantern the ground outside the frustum's square |x|, |z| < 1.2 tan 80 = 6.8); counter
// `projector_clamped` counts such lights.
//
// Why the design is what it is:
//  - Casters stay lit: the silhouette texture has no depth, so a caster cannot tell its own lit side
//    from the shadowed one; the slides render the casters fully lit ("no self shadowing"), and so
//    does this technique (its effects say so: no SelfShadowing).
//  - q > 0: a perspective projection also maps points behind the projector (q < 0) into [0,1]^2, as a
//    mirrored image; without the test a receiver behind a point/spot light would get the caster's
//    silhouette back-projected onto it (the slides' "receiver behind the projector").
//  - Clamp to border, border white: outside the projector's frustum no caster was drawn, so it is lit.
// Problems the slides name that remain by design: an occluder behind a receiver still darkens it
// (there is no depth to compare); for directional lights a receiver between the light and the casters
// is shadowed too (an orthographic projector has no "behind"); soft edges from the blur are a fixed
// width in texture space, not a penumbra that grows with the distance to the caster.
#include <vector>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "scenes/InstanceCulling.h"
#include "techniques/gl/GlTechnique.h"
#include "techniques/gl/SeparableBlur.h"
#include "techniques/projective/Projective.h"

namespace sb {

class ProjectiveGL final : public GlTechnique {
public:
    static constexpr float kMaxHalfAngleDeg = Projective::kMaxHalfAngleDeg;
    using Projector = Projective::Projector;

    ProjectiveGL();
    ~ProjectiveGL() override;
    void setScene(const Scene& scene) override;
    void compile(const CompileContext& ctx) override;
    void execute(FrameContext& ctx) override;
    Counters counters() const override { return mCounters; }

    /// Projective::computeProjector and aimAtReceivers. Public for tests.
    static Projector computeProjector(const Scene& scene, const Light& light) {
        return Projective::computeProjector(scene, light);
    }
    static Projector aimAtReceivers(const Light& light, const Aabb& receivers) {
        return Projective::aimAtReceivers(light, receivers);
    }

private:
    void renderTexture(FrameContext& ctx);
    int renderBlur(FrameContext& ctx); ///< returns the number of blur draws
    void renderLighting(FrameContext& ctx);
    void allocateTextures(int resolution, int layers);
    void releaseTextures();

    std::vector<glm::mat4> mViewProj;      ///< per light with a projector: light camera (clip space)
    std::vector<glm::mat4> mTextureMatrix; ///< per light: bias * viewProj (to [0,1] texture space)
    int mClamped = 0;                      ///< lights whose projector was clamped
    std::vector<uint8_t> mCastsShadows;    ///< per light: false leaves its layer undrawn
    const char* mNoProjector = nullptr;    ///< why the scene needs none (ShadowWork), or nullptr
    GLuint mArray = 0;                     ///< R8 2D array, one layer per light
    std::vector<GLuint> mFbos;             ///< per layer
    SeparableBlur mBlur;                   ///< the texture's blur (its intermediate: R8 2D)
    int mResolution = 0, mLayers = 0, mBlurRadius = 0;
    bool mCull = true;          ///< cull casters whose shadow misses the view (blur 0)
    InstanceCulling mCulling;   ///< the casters' bounds
    Aabb mReceivers;            ///< the non-casters' bounds: where shadows can fall
    std::vector<uint8_t> mKeep; ///< the casters a light's texture keeps
    size_t mCulled = 0;         ///< casters left out over the frame's textures
    const Program* mTextureProgram = nullptr;
    const Program* mLitProgram = nullptr; ///< casters (and everything without projectors)
    const Program* mProjectiveProgram = nullptr;
    Counters mCounters;
};

} // namespace sb
