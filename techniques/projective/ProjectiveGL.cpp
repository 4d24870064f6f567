#include "techniques/projective/ProjectiveGL.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "core/Error.h"
#include "scenes/LightFit.h"
#include "scenes/Math.h"
#include "scenes/ShadowWork.h"

namespace sb {

namespace {
constexpr GLint kMatrixLocation = 8; // projective/texture.vert and common/scene.vert (SHADOW_MAP)
} // namespace

ProjectiveGL::ProjectiveGL() : GlTechnique(Projective::declaration()) {}

ProjectiveGL::~ProjectiveGL() {
    releaseTextures();
}

void ProjectiveGL::setScene(const Scene& scene) {
    mCulling.setScene(scene);
    const Projective::Plan plan = Projective::plan(scene, properties());
    mReceivers = plan.receivers;
    mViewProj = plan.viewProj;
    mTextureMatrix = plan.textureMatrix;
    mCastsShadows = plan.castsShadows;
    mClamped = plan.clamped;
    mNoProjector = plan.noProjector;
}

void ProjectiveGL::releaseTextures() {
    if (!mFbos.empty()) glDeleteFramebuffers(GLsizei(mFbos.size()), mFbos.data());
    mFbos.clear();
    if (mArray) glDeleteTextures(1, &mArray);
    mArray = 0;
    mResolution = mLayers = 0;
}

namespace {
void checkComplete(GLuint fbo) {
    const GLenum status = glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw Error("projective: texture framebuffer incomplete (status 0x" + std::to_string(status) + ")",
                    ExitCode::Failure);
}
} // namespace

void ProjectiveGL::allocateTextures(int resolution, int layers) {
    if (resolution == mResolution && layers == mLayers) return;
    releaseTextures();
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &mArray);
    glTextureStorage3D(mArray, 1, GL_R8, resolution, resolution, layers);
    // Bilinear lookups; outside the projector's frustum no caster was drawn: a white (lit) border.
    glTextureParameteri(mArray, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(mArray, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(mArray, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glTextureParameteri(mArray, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    const float white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    glTextureParameterfv(mArray, GL_TEXTURE_BORDER_COLOR, white);
    mFbos.resize(size_t(layers));
    glCreateFramebuffers(layers, mFbos.data());
    for (int i = 0; i < layers; ++i) {
        glNamedFramebufferTextureLayer(mFbos[size_t(i)], GL_COLOR_ATTACHMENT0, mArray, 0, i);
        glNamedFramebufferDrawBuffer(mFbos[size_t(i)], GL_COLOR_ATTACHMENT0);
        checkComplete(mFbos[size_t(i)]);
    }
    mResolution = resolution;
    mLayers = layers;
}

void ProjectiveGL::compile(const CompileContext& ctx) {
    const PropertySet& p = properties();
    const int layers = std::max<int>(1, int(mViewProj.size()));
    allocateTextures(int(p.getInt(Projective::kResolution)), layers);
    mBlurRadius = int(p.getInt(Projective::kBlur));
    mCull = p.getBool(Projective::kCull) && mBlurRadius == 0;

    const Defines base = withLightKinds(ctx.submitter.defines(), ctx.scene);
    std::string key;
    // Casters (and, without projectors, everything): lit and unshadowed, as `none` draws them.
    Defines lit = base;
    lit["LIGHT_COUNT"] = std::to_string(std::clamp<int>(int(ctx.scene.lights.size()), 1, kMaxLights));
    mLitProgram = &ctx.programs.get({"common/scene.vert", "common/lit.frag", ""}, lit);
    key = mLitProgram->key();
    mTextureProgram = mProjectiveProgram = nullptr;
    if (!mViewProj.empty()) {
        mTextureProgram = &ctx.programs.get({"projective/texture.vert", "projective/texture.frag", ""}, base);
        Defines projective = ctx.defines(); // its lookups follow the scene's exceptions
        projective["SHADOW_MAP"] = "";      // common/scene.vert: vShadowCoord[i] = uShadowMatrix[i] * world
        projective["LIGHT_COUNT"] = std::to_string(mViewProj.size());
        mProjectiveProgram =
            &ctx.programs.get({"common/scene.vert", "projective/lighting.frag", ""}, projective);
        key += "|" + mTextureProgram->key() + "|" + mProjectiveProgram->key();
    }
    // Point-sampled weights and a lit outside (the texture's white border), one channel: R8.
    const SeparableBlur::Settings blur = {.kernel = SeparableBlur::Kernel::PointSampled,
                                          .size = mViewProj.empty() ? 0 : mBlurRadius,
                                          .border = SeparableBlur::Border::One,
                                          .resolution = mResolution,
                                          .format = GL_R8};
    const std::string blurKey = mBlur.compile(ctx.programs, blur);
    if (!blurKey.empty()) key += "|" + blurKey;
    setPermutationKey(key);
}

void ProjectiveGL::renderTexture(FrameContext& ctx) {
    if (mViewProj.empty()) return;
    glViewport(0, 0, mResolution, mResolution);
    glDisable(GL_DEPTH_TEST); // a silhouette: every caster fragment is black, whatever its depth
    mTextureProgram->use();
    const float white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    const glm::mat4 camera = ctx.proj * ctx.view;
    mCulled = 0;
    for (size_t i = 0; i < mViewProj.size(); ++i) {
        if (!mCastsShadows[i]) continue;
        glBindFramebuffer(GL_FRAMEBUFFER, mFbos[i]);
        glClearBufferfv(GL_COLOR, 0, white);
        glUniformMatrix4fv(kMatrixLocation, 1, GL_FALSE, glm::value_ptr(mViewProj[i]));
        // A silhouette with no depth test: a closed caster's front faces cover what it covers.
        const CullView lightView{mViewProj[i], false};
        if (!mCull) {
            ctx.submitter.drawCulled(DrawSet::Casters, lightView);
            continue;
        }
        // A caster whose shadow misses the view puts no texel where a visible receiver looks it up.
        const size_t kept = mCulling.cullShadows(ctx.scene.lights[i], mReceivers, camera, mKeep);
        mCulled += mCulling.count(DrawSet::Casters) - kept;
        if (kept) ctx.submitter.drawCulled(DrawSet::Casters, lightView, mKeep);
    }
    glEnable(GL_DEPTH_TEST);
}

int ProjectiveGL::renderBlur(FrameContext&) {
    if (mViewProj.empty() || mBlurRadius <= 0) return 0;
    return mBlur.apply(mArray, mFbos, mCastsShadows).passes;
}

void ProjectiveGL::renderLighting(FrameContext& ctx) {
    ctx.targets.bind();
    mLitProgram->use();
    const BackFaceScope culling(ctx.submitter, cameraCullView(ctx));
    if (mViewProj.empty()) {
        ctx.submitter.draw(DrawSet::All); // nothing casts: every instance lit
        return;
    }
    // Casters fully lit (no self-shadowing: the texture cannot tell a caster's lit side from its
    // shadowed one), then the receivers with the projected textures.
    ctx.submitter.draw(DrawSet::Casters);
    mProjectiveProgram->use();
    glUniformMatrix4fv(kMatrixLocation, GLsizei(mTextureMatrix.size()), GL_FALSE,
                       glm::value_ptr(mTextureMatrix[0]));
    glBindTextureUnit(0, mArray);
    ctx.submitter.draw(DrawSet::NonCasters);
    glBindTextureUnit(0, 0);
}

void ProjectiveGL::execute(FrameContext& ctx) {
    ctx.submitter.resetStats();
    int blurPasses = 0;
    if (mNoProjector) {
        ctx.passes.skip("texture", mNoProjector);
        ctx.passes.skip("blur", mNoProjector);
    } else {
        ctx.passes.begin("texture");
        renderTexture(ctx);
        if (mBlurRadius > 0) {
            ctx.passes.begin("blur");
            blurPasses = renderBlur(ctx);
        } else {
            ctx.passes.skip("blur", "blur 0");
        }
    }
    ctx.passes.begin("lighting");
    renderLighting(ctx);
    mCounters = Projective::counters(ctx.submitter.stats(), ctx.scene, mResolution, mCastsShadows, blurPasses,
                                     mClamped, mCulled);
}

} // namespace sb
