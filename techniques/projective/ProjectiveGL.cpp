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

namespace {
/// World bounds of the instances that cast no shadow: DrawSet::NonCasters, what the texture is
/// projected onto.
Aabb receiverBounds(const Scene& scene) {
    Aabb bounds;
    for (const Instance& inst : scene.instances)
        if (!inst.castsShadow && inst.mesh < scene.meshes.size())
            bounds.extend(transformBounds(scene.meshes[inst.mesh].computeBounds(), inst.model));
    return bounds;
}

/// `a` and `b`'s common part (empty when they do not meet).
Aabb intersect(const Aabb& a, const Aabb& b) {
    Aabb r;
    if (a.empty() || b.empty()) return r;
    r.min = glm::max(a.min, b.min);
    r.max = glm::min(a.max, b.max);
    if (glm::any(glm::greaterThan(r.min, r.max))) return {};
    return r;
}

bool contains(const Aabb& box, const glm::vec3& p) {
    return glm::all(glm::greaterThanEqual(p, box.min)) && glm::all(glm::lessThanEqual(p, box.max));
}

/// The half-angle that holds a cone of half-angle `exact` off the texture's border: 1% and a quarter
/// degree of padding (the border is white: lit).
float padded(float exact) {
    return exact * 1.01f + glm::radians(0.25f);
}
} // namespace

ProjectiveGL::Projector ProjectiveGL::aimAtReceivers(const Light& light, const Aabb& receivers) {
    const glm::vec3 toCentre = receivers.center() - light.position;
    // The light among the receivers (a room's walls and floor around it) has no one direction
    // towards them: the spot's axis, or straight down.
    glm::vec3 forward = light.type == LightType::Spot ? glm::normalize(light.direction) : glm::vec3(0, -1, 0);
    if (!contains(receivers, light.position) && glm::length(toCentre) > 0.0f)
        forward = glm::normalize(toCentre);
    float cosWidest = 1.0f, deepest = 0.0f;
    for (const glm::vec3& c : receivers.corners()) {
        const glm::vec3 d = c - light.position;
        const float len = glm::length(d);
        if (!(len > 0.0f)) continue;
        cosWidest = std::min(cosWidest, glm::dot(d, forward) / len);
        deepest = std::max(deepest, glm::dot(d, forward));
    }
    Projector p;
    float half = padded(std::acos(std::clamp(cosWidest, -1.0f, 1.0f)));
    if (!(half < glm::radians(kMaxHalfAngleDeg))) {
        half = glm::radians(kMaxHalfAngleDeg);
        p.clamped = true;
    }
    // Far just past the deepest receiver corner: a caster beyond every receiver shadows none of them.
    // Near a thousandth of it: a silhouette has no depth to resolve, so only clipping matters, and
    // everything between the light and the receivers belongs in the texture.
    const float farZ = std::max(deepest * 1.01f, 1e-4f);
    const glm::mat4 view = glm::lookAt(light.position, light.position + forward, anyPerpendicularUp(forward));
    p.viewProj = glm::perspective(2.0f * half, 1.0f, 1e-3f * farZ, farZ) * view;
    return p;
}

ProjectiveGL::Projector ProjectiveGL::computeProjector(const Scene& scene, const Light& light) {
    if (light.type == LightType::Directional) return {fitLightViewProjection(scene, light), false};
    // Point and spot: a perspective projector at the light looking at the casters' bounding sphere.
    const Aabb casters = scene.computeBounds(true);
    const glm::vec3 centre = casters.center();
    const float radius = std::max(0.5f * glm::length(casters.extent()), 1e-4f);
    const glm::vec3 toCentre = centre - light.position;
    const float dist = glm::length(toCentre);
    if (!(dist > radius)) {
        // Inside the sphere the casters are all around the light; what can shadow a receiver lies
        // between the light and the receivers (within the range, beyond which nothing is lit).
        Aabb receivers = receiverBounds(scene);
        if (light.range > 0.0f)
            receivers = intersect(receivers, Aabb{light.position - glm::vec3(light.range),
                                                  light.position + glm::vec3(light.range)});
        if (!receivers.empty()) return aimAtReceivers(light, receivers);
    }
    // The light at the centre itself has no direction towards it: the spot's axis, or straight down.
    glm::vec3 forward = toCentre / dist;
    if (!(dist > 1e-6f * radius))
        forward = light.type == LightType::Spot ? glm::normalize(light.direction) : glm::vec3(0, -1, 0);
    const float maxHalf = glm::radians(kMaxHalfAngleDeg);
    Projector p;
    float half = maxHalf;
    // The sphere subtends asin(r / dist) around the axis.
    if (dist > radius) half = padded(std::asin(radius / dist));
    if (!(half < maxHalf)) {
        half = maxHalf;
        p.clamped = true;
    }
    const float nearZ = std::max(dist - radius, 1e-3f * std::max(dist, radius));
    const float farZ = std::max(dist + radius, 2.0f * nearZ);
    const glm::mat4 view = glm::lookAt(light.position, light.position + forward, anyPerpendicularUp(forward));
    p.viewProj = glm::perspective(2.0f * half, 1.0f, nearZ, farZ) * view;
    return p;
}

void ProjectiveGL::setScene(const Scene& scene) {
    mCulling.setScene(scene);
    mReceivers = receiverBounds(scene);
    mViewProj.clear();
    mTextureMatrix.clear();
    mCastsShadows.clear();
    mClamped = 0;
    // No casters, no light that casts, or no receiver: nothing to project, everything is lit (and the
    // frame does no texture work).
    mNoProjector =
        scene.computeBounds(true).empty() ? "no instance casts a shadow" : ShadowWork::noneNeeded(scene);
    if (mNoProjector) return;
    const size_t count = std::min<size_t>(scene.lights.size(), kMaxLights);
    const glm::mat4 bias =
        glm::translate(glm::mat4(1.0f), glm::vec3(0.5f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));
    for (size_t i = 0; i < count; ++i) {
        mCastsShadows.push_back(scene.lights[i].castsShadows);
        if (!scene.lights[i].castsShadows) { // a layer never drawn nor looked up (common/lighting.glsl)
            mViewProj.emplace_back(1.0f);
            mTextureMatrix.push_back(bias);
            continue;
        }
        const Projector p = computeProjector(scene, scene.lights[i]);
        mViewProj.push_back(p.viewProj);
        mTextureMatrix.push_back(bias * p.viewProj);
        mClamped += p.clamped;
    }
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

    const Defines base = ctx.submitter.defines();
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
        if (!mCull) {
            ctx.submitter.draw(DrawSet::Casters);
            continue;
        }
        // A caster whose shadow misses the view puts no texel where a visible receiver looks it up.
        const size_t kept = mCulling.cullShadows(ctx.scene.lights[i], mReceivers, camera, mKeep);
        mCulled += mCulling.count(DrawSet::Casters) - kept;
        if (kept) ctx.submitter.draw(DrawSet::Casters, mKeep);
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
    const SubmitStats& s = ctx.submitter.stats();
    mCounters = {{"draw_calls", double(s.drawCalls)},
                 {"triangles", double(s.triangles)},
                 {"projective_texels", double(mResolution) * mResolution *
                                           double(std::count(mCastsShadows.begin(), mCastsShadows.end(), 1))},
                 {"blur_passes", double(blurPasses)},
                 {"projector_clamped", double(mClamped)},
                 {"casters_culled", double(mCulled)},
                 {"lights_unshadowed", double(ShadowWork::unshadowedLights(ctx.scene, kMaxLights))}};
}

} // namespace sb
