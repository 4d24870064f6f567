#pragma once
// The depth pass that filterable shadow maps share (`vsm`, `esm`, `evsm`, `msm`) on GL (the fits, the
// culling and the counters both APIs share are techniques/shadowmap/MomentMapFits.h): per light one layer
// of a colour texture array (RG32F moments for VSM, R32F depth for ESM, RG32F or RGBA32F warped moments for
// EVSM, RGBA16 or RGBA32F four moments for MSM) holding what the technique's program writes
// from each caster fragment, rendered with a depth buffer (one renderbuffer for all layers) so the nearest
// caster wins, and cleared to "no occluder" (depth 1) first.
//
// The stored depth is *linear* light-space depth in [0, 1], not the window depth of the projection:
// filtering (bilinear, blur) averages depths, which is only meaningful in a space where the average of two
// depths is a depth between them (Donnelly and Lauritzen 2006, Variance Shadow Maps, section 3.1; Annen et
// al. 2008, Exponential Shadow Maps, section 3). Directional lights: the orthographic map of
// scenes/LightFit.h, whose window depth is linear along the light, rescaled so that [0, 1] is the depth
// range the scene covers inside the map's frustum. Spot lights: the perspective map of the same fit for the
// texel positions, the distance to the light for depth, d = |p - light| / dMax with dMax the farthest
// distance from the light of anything inside the frustum. "What the scene covers inside the frustum" is
// each instance's bounding box clipped to the frustum (its corners, exactly: the vertices where three of
// the box's and the frustum's planes meet), not the scene's bounds: the fit's own depth range covers every
// instance whole, and a 200-unit ground under 1-unit casters (`teapot`) squeezed their shadows' depth
// differences into 1% of it, where ESM's exponent and VSM's minimum variance, both defined on d in [0, 1],
// saw almost none (`esm` at c = 80 on teapot, 1024^2 frame: 1.04% wrong against the reference with the
// fit's range, most of the small shadows gone; 0.42% with the clipped one). The
// lighting passes compute the receiver's d with the same function (shaders/shadowmap/light_depth.glsl),
// from the uniforms depthPlanes() and depthPoints(). Point lights need an omni map (`cubemap`,
// `paraboloid`) and are refused with ExitCode::Unsupported.
//
// The receiver background. A filtered lookup averages the depths of the region around the receiver; at an
// occluder's edge the rest of that region is what the map holds beside the occluder. With casters alone
// that is the cleared depth 1, far behind the receiver, and both bounds read a region partly covered by
// the occluder as mostly lit: VSM's Chebyshev bound is far from tight for a receiver close behind its
// occluder with a distant second depth (the two-depth case of Lauritzen 2007, section 8.4.3), and ESM's
// exp(c (1 - t)) outweighs the occluder's share until it covers nearly all of the region. Measured on
// `aircraft` (thin wing shadows a few texels wide; 1024^2 frame against the reference): 1.33% (vsm) and
// 1.81% (esm) wrong without it, 0.34% and 0.32% with it. So each light's pass
// first draws the non-casters (grounds, walls) keeping the *farthest* one per texel, then the casters over
// a cleared depth buffer keeping the nearest: a texel holds the nearest caster if there is one, else the
// farthest non-caster, else 1. Every non-caster point at that texel lies at or in front of what is stored,
// so a non-caster still shadows nothing (the scene's casts_shadow holds), and behind an occluder's edge the
// filter sees the receiver's own depth: for one occluder over a plane the VSM bound is then exact
// (two depths, the receiver at the deeper: p_max = 1 - coverage) and ESM's edge sits at half coverage.
// Property `receiver_background` turns it off (casters alone, as `shadowmap` draws its map).
//
// The margin. A filtered lookup reads texels around it: the bilinear footprint one texel, the blur r =
// blur / 2 texels each way before that. Within r + 1 texels of the map's border those reads run off the
// map and return the edge texel (clamp to edge), a constant where the receiver background keeps sloping:
// measured, a ground sloped in light space read 0.83 lit at the border of a 256^2 map. So the fitted
// frustum is widened until the casters fill only the inner resolution - 2 (r + 1) texels, and lookups in
// the outer r + 1 texels answer "lit" without sampling (no caster is there): every texel a lookup reads is
// one that was rendered and blurred from rendered texels.
//
// Each light's pass submits only the casters whose bounds reach its frustum (scenes/
// InstanceCulling.h, all six planes, as `shadowmap`); a light whose frustum holds no caster gets its layer
// cleared and nothing else (layerHasCasters() says which, so the blur can skip it too).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "techniques/gl/ContactShadowsGL.h"
#include "techniques/gl/GlTechnique.h"
#include "techniques/gl/LitPrograms.h"
#include "techniques/gl/SeparableBlur.h"
#include "techniques/shadowmap/MomentMapFits.h"

namespace sb {

class FilterableShadowMaps {
public:
    /// Uniform locations the depth program and the lighting programs share (shaders/shadowmap/
    /// moments.vert, light_depth.glsl): the light's view-projection (depth pass) or the shadow matrices
    /// (lighting, common/scene.vert), and the depth parameters of the depth pass's light (one each) or of
    /// every light (arrays of LIGHT_COUNT).
    static constexpr GLint kLightMatrixLocation = 8;
    static constexpr GLint kDepthPlaneLocation = 32;
    static constexpr GLint kDepthPointLocation = 36;
    static constexpr GLint kMarginLocation = 44; ///< lighting: the margin in texture coordinates

    explicit FilterableShadowMaps(std::string owner) : mOwner(owner), mFits(std::move(owner)) {}
    ~FilterableShadowMaps();
    FilterableShadowMaps(const FilterableShadowMaps&) = delete;
    FilterableShadowMaps& operator=(const FilterableShadowMaps&) = delete;

    /// The light fits (MomentMapFits): setScene, sceneChanged, fit, the receiver background and the
    /// view culling are set there.
    MomentMapFits& fits() { return mFits; }
    const MomentMapFits& fits() const { return mFits; }
    /// (Re)allocates the array, the depth renderbuffer and the framebuffers when the size or format
    /// changed. `format`: GL_RG32F, GL_R32F, GL_RGBA32F or GL_RGBA16. Bilinear filtering, clamp to edge.
    void allocate(int resolution, GLenum format);

    /// The depth pass: binds `program` (which must write the light's moments to colour 0), and per light
    /// clears its layer to `clear` (depth 1 in the technique's encoding), sets the light's matrix and
    /// depth parameters and, if any caster reaches its frustum, draws with the receiver background the
    /// non-casters its frustum keeps (the farthest per texel), then over a cleared depth buffer the
    /// casters it keeps (the nearest per texel).
    void render(FrameContext& ctx, const Program& program, const glm::vec4& clear);
    /// Sets the lighting program's uniforms: shadow matrices and depth parameters of every light.
    void setLightingUniforms() const;
    /// One frame of a moment technique (`vsm`, `esm`, which differ only in programs, blur mode and the
    /// lighting's own uniforms): resets the submit stats; with contact on, pass "view_depth", `contact`'s
    /// pre-pass (techniques/gl/ContactShadowsGL.h); pass "depth", render() with `depth` and `clear`; pass
    /// "blur", `blur` over the layers a caster reached; pass "lighting", the frame targets bound,
    /// `lighting`'s program used, setLightingUniforms(), `setUniforms` for the technique's own, the maps on
    /// unit 0, `contact` bound, everything drawn (LitPrograms::draw). Returns the frame's counters
    /// (MomentMapFits::counters).
    Counters renderFrame(FrameContext& ctx, const Program& depth, const glm::vec4& clear, SeparableBlur& blur,
                         const LitPrograms& lighting, const std::function<void()>& setUniforms,
                         ContactShadowsGL& contact);

    int layers() const { return mLayers; }
    int resolution() const { return mResolution; }
    GLuint texture() const { return mArray; }
    const std::vector<GLuint>& framebuffers() const { return mFbos; }
    /// Per layer: whether the last render() drew any caster into it.
    const std::vector<uint8_t>& layerHasCasters() const { return mHasCasters; }
    size_t castersCulled() const { return mCulled; }

private:
    void release();

    std::string mOwner; ///< technique name, for error messages
    MomentMapFits mFits;
    GLuint mArray = 0, mDepthBuffer = 0;
    std::vector<GLuint> mFbos;
    int mResolution = 0, mLayers = 0;
    GLenum mFormat = 0;
    std::vector<uint8_t> mKeep, mKeepBackground, mHasCasters;
    size_t mCulled = 0;
};

} // namespace sb
