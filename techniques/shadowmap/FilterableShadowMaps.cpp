#include "techniques/shadowmap/FilterableShadowMaps.h"

#include <algorithm>

#include <glm/gtc/type_ptr.hpp>

#include "core/Error.h"
#include "scenes/ShadowWork.h"
#include "techniques/ContactShadows.h"

namespace sb {

FilterableShadowMaps::~FilterableShadowMaps() {
    release();
}

void FilterableShadowMaps::release() {
    if (!mFbos.empty()) glDeleteFramebuffers(GLsizei(mFbos.size()), mFbos.data());
    mFbos.clear();
    if (mArray) glDeleteTextures(1, &mArray);
    if (mDepthBuffer) glDeleteRenderbuffers(1, &mDepthBuffer);
    mArray = mDepthBuffer = 0;
    mResolution = mLayers = 0;
    mFormat = 0;
}

void FilterableShadowMaps::allocate(int resolution, GLenum format) {
    const int layers = std::max<int>(1, int(mFits.lights()));
    if (resolution == mResolution && layers == mLayers && format == mFormat) return;
    release();
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &mArray);
    glTextureStorage3D(mArray, 1, format, resolution, resolution, layers);
    // Bilinear: filtering the stored moments is the point of these maps. Lookups outside [0, 1]^2 are
    // answered "lit" by the shaders before they sample, so the wrap mode only matters for the filter's
    // footprint at the border.
    glTextureParameteri(mArray, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(mArray, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(mArray, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(mArray, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glCreateRenderbuffers(1, &mDepthBuffer);
    glNamedRenderbufferStorage(mDepthBuffer, GL_DEPTH_COMPONENT24, resolution, resolution);
    mFbos.resize(size_t(layers));
    glCreateFramebuffers(layers, mFbos.data());
    for (int i = 0; i < layers; ++i) {
        const GLuint fbo = mFbos[size_t(i)];
        glNamedFramebufferTextureLayer(fbo, GL_COLOR_ATTACHMENT0, mArray, 0, i);
        glNamedFramebufferRenderbuffer(fbo, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, mDepthBuffer);
        glNamedFramebufferDrawBuffer(fbo, GL_COLOR_ATTACHMENT0);
        const GLenum status = glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER);
        if (status != GL_FRAMEBUFFER_COMPLETE)
            throw Error(mOwner + ": shadow map framebuffer incomplete (status 0x" + std::to_string(status) +
                            ")",
                        ExitCode::Failure);
    }
    mHasCasters.assign(size_t(layers), 0);
    mResolution = resolution;
    mLayers = layers;
    mFormat = format;
}

void FilterableShadowMaps::render(FrameContext& ctx, const Program& program, const glm::vec4& clear) {
    glViewport(0, 0, mResolution, mResolution);
    program.use();
    mCulled = 0;
    const float nearest = 0.0f, farthest = 1.0f;
    const glm::mat4 camera = ctx.proj * ctx.view;
    for (size_t i = 0; i < mFits.lights(); ++i) {
        if (!mFits.castsShadow(i)) { // never looked up (common/lighting.glsl): neither cleared nor blurred
            mHasCasters[i] = 0;
            continue;
        }
        glBindFramebuffer(GL_FRAMEBUFFER, mFbos[i]);
        glClearBufferfv(GL_COLOR, 0, glm::value_ptr(clear));
        const MomentMapFits::LightDraws draws =
            mFits.cull(i, ctx.scene, camera, mKeep, mKeepBackground, mCulled);
        mHasCasters[i] = draws.casters > 0;
        if (draws.casters == 0) continue; // no caster reaches this light's map: it stays "no occluder"
        glUniformMatrix4fv(kLightMatrixLocation, 1, GL_FALSE, glm::value_ptr(mFits.viewProjections()[i]));
        glUniform4fv(kDepthPlaneLocation, 1, glm::value_ptr(mFits.depthPlanes()[i]));
        glUniform4fv(kDepthPointLocation, 1, glm::value_ptr(mFits.depthPoints()[i]));
        if (draws.background) {
            // The farthest non-caster per texel (GREATER over a depth buffer cleared to 0): every
            // non-caster there lies at or in front of it, so none is shadowed by it.
            glClearBufferfv(GL_DEPTH, 0, &nearest);
            glDepthFunc(GL_GREATER);
            ctx.submitter.draw(DrawSet::NonCasters, mKeepBackground);
            glDepthFunc(GL_LESS);
        }
        // The nearest caster per texel, over whatever the background left.
        glClearBufferfv(GL_DEPTH, 0, &farthest);
        // The nearest caster per texel may lose closed casters' back faces; the background above keeps
        // both (the farthest surface of a closed mesh is a back face).
        ctx.submitter.drawCulled(DrawSet::Casters, {mFits.viewProjections()[i], false}, mKeep);
    }
}

void FilterableShadowMaps::setLightingUniforms() const {
    if (mFits.viewProjections().empty()) return;
    const GLsizei n = GLsizei(mFits.lights());
    glUniformMatrix4fv(kLightMatrixLocation, n, GL_FALSE, glm::value_ptr(mFits.shadowMatrices()[0]));
    glUniform4fv(kDepthPlaneLocation, n, glm::value_ptr(mFits.depthPlanes()[0]));
    glUniform4fv(kDepthPointLocation, n, glm::value_ptr(mFits.depthPoints()[0]));
    glUniform1f(kMarginLocation, mFits.marginUv(mResolution));
}

Counters FilterableShadowMaps::renderFrame(FrameContext& ctx, const Program& depth, const glm::vec4& clear,
                                           SeparableBlur& blur, const LitPrograms& lighting,
                                           const std::function<void()>& setUniforms,
                                           ContactShadowsGL& contact) {
    ctx.submitter.resetStats();
    double blurTexels = 0.0;
    const std::function<void()> viewDepth = contact.prePass(ctx);
    if (const char* reason = ShadowWork::noneNeeded(ctx.scene)) {
        if (viewDepth) ctx.passes.skip(ContactShadows::kPass, reason);
        ctx.passes.skip("depth", reason);
        ctx.passes.skip("blur", reason);
    } else {
        if (viewDepth) {
            ctx.passes.begin(ContactShadows::kPass);
            viewDepth();
        }
        ctx.passes.begin("depth");
        render(ctx, depth, clear);
        if (blur.radius() > 0) {
            ctx.passes.begin("blur");
            blurTexels = blur.apply(texture(), framebuffers(), layerHasCasters()).texels;
        } else {
            ctx.passes.skip("blur", "blur below 2 texels: a one-tap kernel");
        }
    }
    ctx.passes.begin("lighting");
    ctx.targets.bind();
    lighting.program().use();
    setLightingUniforms();
    setUniforms();
    glBindTextureUnit(0, texture());
    contact.bind();
    lighting.draw(ctx.submitter, cameraCullView(ctx));
    contact.unbind();
    glBindTextureUnit(0, 0);
    return mFits.counters(ctx.submitter.stats(), resolution(), blurTexels, castersCulled());
}

} // namespace sb
