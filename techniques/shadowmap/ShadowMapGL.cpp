#include "techniques/shadowmap/ShadowMapGL.h"
#include "techniques/shadowmap/FlatLightsGL.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "core/Injection.h"
#include "scenes/Math.h"
#include "techniques/ContactShadows.h"
#include "techniques/DepthLightingFrame.h"
#include "techniques/ShadowMapProperties.h"
#include "techniques/shadowmap/DepthPassState.h"
#include "techniques/shadowmap/PoissonDisk.h"

namespace sb {

namespace {
using P = ShadowMapProperties;
// shadowmap/lighting.frag: uTexelWorld[LIGHT_COUNT], uNormalOffset, uKernelTaps, uKernel[64].
constexpr GLint kTexelWorldLocation = 12;
constexpr GLint kNormalOffsetLocation = 16;
constexpr GLint kKernelTapsLocation = 17;
constexpr GLint kKernelLocation = 20; // uKernel[64]

} // namespace

ShadowMapGL::ShadowMapGL() : GlTechnique(ShadowMap::declaration()) {}

void ShadowMapGL::propertiesApplied() {
    mutableInfo().passes = ContactShadows::passes(properties(), ShadowMap::declaration().passes);
}

void ShadowMapGL::setScene(const Scene& scene) {
    mLights.setScene(scene, "shadowmap", properties());
    mCulling.setScene(scene);
}

void ShadowMapGL::compile(const CompileContext& ctx) {
    const PropertySet& p = properties();
    int layers = std::max<int>(1, int(mLights.size()));
    // The perf gate's proof may double the map per side (core/Injection.h); the row's properties
    // still say the configured resolution, its `injected` column says what ran.
    const int scale = injected(Injection::DoubleShadowResolution) ? 2 : 1;
    mMaps.allocate(GL_TEXTURE_2D_ARRAY, scale * int(p.getInt(P::kResolution)), layers, false);
    const GLuint depthArray = mMaps.texture();
    bool hw = p.getBool(ShadowMap::kHardwareCompare);
    // Hardware compare: LINEAR filters the four comparison results (bilinear PCF); without it the shader
    // compares NEAREST depth values itself.
    glTextureParameteri(depthArray, GL_TEXTURE_COMPARE_MODE, hw ? GL_COMPARE_REF_TO_TEXTURE : GL_NONE);
    glTextureParameteri(depthArray, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glTextureParameteri(depthArray, GL_TEXTURE_MIN_FILTER, hw ? GL_LINEAR : GL_NEAREST);
    glTextureParameteri(depthArray, GL_TEXTURE_MAG_FILTER, hw ? GL_LINEAR : GL_NEAREST);

    mDrawAllIntoMap = injected(Injection::NoCasterCulling);
    Defines base = ctx.submitter.defines();
    mDepthProgram = &ctx.programs.get({"common/depth.vert", "common/depth.frag", ""}, base);
    mContact.compile(p, ctx.programs, base);
    // The depth pass has no shadow to apply: only the lighting pass takes the scene's exceptions.
    const Defines lit = ShadowMap::lightingDefines(ctx.defines(), p, layers);
    mKernel = ShadowMap::kernelOffsets(p);
    mNormalOffset = float(p.getFloat(ShadowMap::kNormalOffset));
    mCull = p.getBool(ShadowMap::kCull);
    fitTexels(ctx.scene);
    const ShaderSources lighting{"common/scene.vert", "shadowmap/lighting.frag", ""};
    setPermutationKey(mDepthProgram->key() + "|" + mLighting.compile(ctx, lighting, lit));
}

void ShadowMapGL::sceneChanged(const Scene& scene, uint32_t) {
    setScene(scene);
    fitTexels(scene);
}

void ShadowMapGL::fitTexels(const Scene& scene) {
    const PropertySet& p = properties();
    const double kernel = mKernel.empty() ? double(p.getInt(P::kPcf)) : p.getFloat(ShadowMap::kRadius);
    ShadowMap::fitTexels(scene, mLights, mMaps.size(), kernel, mNormalOffset, mTexelWorld, mView);
}

void ShadowMapGL::renderDepth(FrameContext& ctx) {
    const PropertySet& p = properties();
    DepthPassState state(mMaps.size(), float(p.getFloat(P::kBiasSlope)), float(p.getFloat(P::kBiasConstant)));
    mDepthProgram->use();
    // Only casters inside the light's frustum reach the map; the gate's proof can lose that culling
    // (core/Injection.h).
    mView.reach.camera = ctx.proj * ctx.view;
    mCulled = renderFlatDepth(mLights, ctx.submitter, mCulling, mMaps, mKeep, mDrawAllIntoMap,
                              mCull && !mDrawAllIntoMap ? &mView : nullptr);
}

void ShadowMapGL::renderLighting(FrameContext& ctx) {
    ctx.targets.bind();
    mLighting.program().use();
    setFlatShadowMatrices(mLights);
    if (mNormalOffset > 0.0f) {
        glUniform1fv(kTexelWorldLocation, GLsizei(mTexelWorld.size()), mTexelWorld.data());
        glUniform1f(kNormalOffsetLocation, mNormalOffset);
    }
    if (!mKernel.empty()) {
        glUniform1i(kKernelTapsLocation, GLint(mKernel.size()));
        glUniform2fv(kKernelLocation, GLsizei(mKernel.size()), glm::value_ptr(mKernel[0]));
    }
    glBindTextureUnit(0, mMaps.texture());
    mContact.bind();
    mLighting.draw(ctx.submitter, cameraCullView(ctx));
    mContact.unbind();
    glBindTextureUnit(0, 0);
}

void ShadowMapGL::execute(FrameContext& ctx) {
    const SubmitStats s = DepthLightingFrame::run(
        ctx, [&] { renderDepth(ctx); }, [&] { renderLighting(ctx); }, mContact.prePass(ctx),
        ContactShadows::kPass);
    mCounters = ShadowMap::counters(s, mMaps.size(), mLights, mCulled);
}

} // namespace sb
