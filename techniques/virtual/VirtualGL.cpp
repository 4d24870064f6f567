#include "techniques/virtual/VirtualGL.h"

#include <algorithm>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "core/Error.h"
#include "scenes/LightFit.h"
#include "scenes/Motion.h"
#include "shading/ShaderLimits.h"
#include "techniques/DepthLightingFrame.h"
#include "techniques/FlatLightFits.h"
#include "techniques/ShadowMapProperties.h"
#include "techniques/virtual/Virtual.h"

namespace sb {

namespace {
using P = ShadowMapProperties;
// common/depth.vert's light matrix; shaders/virtual/*'s uniforms.
constexpr GLint kLightViewProjLocation = 8;
constexpr GLint kLightMatrixLocation = 10;    // mark.frag, lighting.frag: bias * viewProj
constexpr GLint kMarkLocation = 14;           // mark.frag: 0 in the depth draw, 1 in the marking draw
constexpr GLint kBiasLocation = 10;           // page_depth.frag: (constant, slope)
constexpr uint32_t kClearDepth = 0x3f800000u; // floatBitsToUint(1.0): nothing drawn, lit

GLuint r32uiTexture(int size) {
    GLuint t = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &t);
    glTextureStorage2D(t, 1, GL_R32UI, size, size);
    // Integer textures are read with texelFetch; NEAREST keeps them complete.
    glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return t;
}

/// The clip-space crop that takes the pages [x0, x1] of row y to [-1, 1]^2: what the run's casters are
/// culled against (never drawn with: the pages are drawn in the whole map's coordinates).
glm::mat4 cropToRun(const PageGeometry& g, int x0, int x1, int y) {
    const float n = float(g.pagesPerSide());
    const glm::vec2 lo(2.0f * float(x0) / n - 1.0f, 2.0f * float(y) / n - 1.0f);
    const glm::vec2 hi(2.0f * float(x1 + 1) / n - 1.0f, 2.0f * float(y + 1) / n - 1.0f);
    glm::mat4 crop(1.0f);
    crop[0][0] = 2.0f / (hi.x - lo.x);
    crop[1][1] = 2.0f / (hi.y - lo.y);
    crop[3][0] = -(hi.x + lo.x) / (hi.x - lo.x);
    crop[3][1] = -(hi.y + lo.y) / (hi.y - lo.y);
    return crop;
}

void requireLimit(GLenum what, const char* name, int needed) {
    GLint v[2] = {0, 0};
    glGetIntegerv(what, v);
    if (v[0] < needed)
        throw Error("virtual needs " + std::string(name) + " >= " + std::to_string(needed) +
                        " (virtual_resolution); this context has " + std::to_string(v[0]),
                    ExitCode::Unsupported);
}

} // namespace

VirtualGL::VirtualGL() : GlTechnique(Virtual::declaration()) {}

VirtualGL::~VirtualGL() {
    release();
}

void VirtualGL::release() {
    for (GLuint* t : {&mRequests, &mTable, &mAtlas}) {
        if (*t) glDeleteTextures(1, t);
        *t = 0;
    }
    if (mEmptyFbo) glDeleteFramebuffers(1, &mEmptyFbo);
    mEmptyFbo = 0;
}

void VirtualGL::setScene(const Scene& scene) {
    mLight = -1;
    for (size_t i = 0; i < scene.lights.size() && i < size_t(kMaxLights); ++i) {
        const Light& l = scene.lights[i];
        if (!l.castsShadows) continue;
        if (l.type != LightType::Directional)
            throw Error("virtual: light " + std::to_string(i) + " is a " + lightTypeName(l.type) +
                            " light; this first form maps directional lights only",
                        ExitCode::Unsupported);
        if (mLight >= 0)
            throw Error("virtual: lights " + std::to_string(mLight) + " and " + std::to_string(i) +
                            " both cast shadows; this first form maps one light",
                        ExitCode::Unsupported);
        mLight = int(i);
    }
    mCache.emplace(Virtual::geometry(properties()));
    mCulling.setScene(scene);
    mMoved.clear();
    fitLight(scene);
}

void VirtualGL::fitLight(const Scene& scene) {
    if (mLight < 0) return;
    mLightViewProj = fitLightViewProjection(scene, scene.lights[size_t(mLight)], {LightFitBounds::Scene});
    mCasters.reset(scene, mLightViewProj, mCache->geometry(), 1.0f);
}

void VirtualGL::sceneChanged(const Scene& scene, uint32_t changes) {
    if (changes & kCastersMoved) mCulling.instancesMoved(scene);
    if (changes & kLightsMoved)
        fitLight(scene); // a new transform: beginFrame drops every page
    else if (changes & kCastersMoved)
        mCasters.moved(scene, mMoved);
}

void VirtualGL::compile(const CompileContext& ctx) {
    release();
    const PropertySet& p = properties();
    const PageGeometry& g = mCache->geometry();
    requireLimit(GL_MAX_VIEWPORT_DIMS, "GL_MAX_VIEWPORT_DIMS", g.virtualResolution());
    requireLimit(GL_MAX_FRAMEBUFFER_WIDTH, "GL_MAX_FRAMEBUFFER_WIDTH", g.virtualResolution());
    requireLimit(GL_MAX_FRAMEBUFFER_HEIGHT, "GL_MAX_FRAMEBUFFER_HEIGHT", g.virtualResolution());
    requireLimit(GL_MAX_TEXTURE_SIZE, "GL_MAX_TEXTURE_SIZE", g.atlasResolution());
    mRequests = r32uiTexture(g.pagesPerSide());
    mTable = r32uiTexture(g.pagesPerSide());
    mAtlas = r32uiTexture(g.atlasResolution());
    const uint32_t zero = 0;
    glClearTexImage(mTable, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    glCreateFramebuffers(1, &mEmptyFbo);
    glNamedFramebufferParameteri(mEmptyFbo, GL_FRAMEBUFFER_DEFAULT_WIDTH, g.virtualResolution());
    glNamedFramebufferParameteri(mEmptyFbo, GL_FRAMEBUFFER_DEFAULT_HEIGHT, g.virtualResolution());

    Defines pages;
    Virtual::addPageDefines(p, pages);
    Defines mark = ctx.defines();
    mark.insert(pages.begin(), pages.end());
    mMarkProgram = &ctx.programs.get({"common/scene.vert", "virtual/mark.frag", ""}, mark);
    Defines depth = ctx.submitter.defines();
    depth.insert(pages.begin(), pages.end());
    mPageProgram = &ctx.programs.get({"common/depth.vert", "virtual/page_depth.frag", ""}, depth);
    Defines lit = ctx.defines();
    lit.insert(pages.begin(), pages.end());
    lit["LIGHT_COUNT"] = std::to_string(std::max<size_t>(1, ctx.scene.lights.size()));
    lit["MAPPED_LIGHT"] = std::to_string(mLight);
    setPermutationKey(mMarkProgram->key() + "|" + mPageProgram->key() + "|" +
                      mLighting.compile(ctx, {"common/scene.vert", "virtual/lighting.frag", ""}, lit));
}

void VirtualGL::markPages(FrameContext& ctx) {
    const uint32_t zero = 0;
    glClearTexImage(mRequests, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    ctx.targets.bind();
    mMarkProgram->use();
    const glm::mat4 shadow = FlatLightFits::textureBias() * mLightViewProj;
    glUniformMatrix4fv(kLightMatrixLocation, 1, GL_FALSE, glm::value_ptr(shadow));
    glBindImageTexture(0, mRequests, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32UI);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT); // the clear before the stores
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    // The receivers' depth first, then the same draws again where the depth is equal: with early
    // fragment tests only the visible fragment of each pixel marks (the same program: invariant depth).
    glUniform1i(kMarkLocation, 0);
    ctx.submitter.drawCulled(DrawSet::Receivers, cameraCullView(ctx));
    glDepthFunc(GL_EQUAL);
    glDepthMask(GL_FALSE);
    glUniform1i(kMarkLocation, 1);
    ctx.submitter.drawCulled(DrawSet::Receivers, cameraCullView(ctx));
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClearBufferfi(GL_DEPTH_STENCIL, 0, 1.0f, 0); // the lighting pass starts from the harness's clear
    glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32UI);
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT); // the stores before the read-back
}

void VirtualGL::allocatePages() {
    const PageGeometry& g = mCache->geometry();
    mWords.resize(g.pageCount());
    glGetTextureImage(mRequests, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, GLsizei(mWords.size() * 4),
                      mWords.data());
    mNeeded.assign(g.pageCount(), 0);
    for (size_t i = 0; i < mWords.size(); ++i) mNeeded[i] = mWords[i] != 0 ? 1 : 0;
    mCache->beginFrame(mLightViewProj, properties().getBool(Virtual::kCache));
    mCache->invalidate(mMoved);
    mMoved.clear();
    mCache->allocate(mNeeded);
    mCache->packTable(mWords);
    glTextureSubImage2D(mTable, 0, 0, 0, g.pagesPerSide(), g.pagesPerSide(), GL_RED_INTEGER, GL_UNSIGNED_INT,
                        mWords.data());
    for (uint32_t page : mCache->renderList()) {
        const glm::ivec2 o = g.atlasOrigin(mCache->table().slot(page));
        glClearTexSubImage(mAtlas, 0, o.x, o.y, 0, g.pageSize(), g.pageSize(), 1, GL_RED_INTEGER,
                           GL_UNSIGNED_INT, &kClearDepth);
    }
}

void VirtualGL::renderPages(FrameContext& ctx) {
    const PageGeometry& g = mCache->geometry();
    const PropertySet& p = properties();
    glBindFramebuffer(GL_FRAMEBUFFER, mEmptyFbo);
    glViewport(0, 0, g.virtualResolution(), g.virtualResolution());
    glEnable(GL_SCISSOR_TEST);
    glEnable(GL_DEPTH_CLAMP); // casters nearer the light than the fit's near side still shadow
    mPageProgram->use();
    glUniformMatrix4fv(kLightViewProjLocation, 1, GL_FALSE, glm::value_ptr(mLightViewProj));
    glUniform2f(kBiasLocation, float(p.getFloat(P::kBiasConstant)), float(p.getFloat(P::kBiasSlope)));
    glBindImageTexture(0, mAtlas, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
    glBindTextureUnit(1, mTable);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    const std::vector<uint32_t>& pages = mCache->renderList();
    for (size_t i = 0; i < pages.size();) {
        // A run: pages of one row with consecutive numbers (the list is in page order).
        size_t j = i + 1;
        while (j < pages.size() && pages[j] == pages[j - 1] + 1 &&
               g.pageCoord(pages[j]).y == g.pageCoord(pages[i]).y)
            ++j;
        const glm::ivec2 first = g.pageCoord(pages[i]);
        const int count = int(j - i);
        glScissor(first.x * g.pageSize(), first.y * g.pageSize(), count * g.pageSize(), g.pageSize());
        const glm::mat4 run = cropToRun(g, first.x, first.x + count - 1, first.y) * mLightViewProj;
        mCulling.cull(run, DrawSet::Casters, CullPlanes::SidesAndFar, mKeep);
        ctx.submitter.drawCulled(DrawSet::Casters, {mLightViewProj, true}, mKeep);
        i = j;
    }
    glDisable(GL_DEPTH_CLAMP);
    glDisable(GL_SCISSOR_TEST);
    glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
    glBindTextureUnit(1, 0);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT); // the atomics before the lighting pass's fetches
    mCache->rendered();
}

void VirtualGL::renderLighting(FrameContext& ctx) {
    ctx.targets.bind();
    mLighting.program().use();
    const glm::mat4 shadow = FlatLightFits::textureBias() * mLightViewProj;
    glUniformMatrix4fv(kLightMatrixLocation, 1, GL_FALSE, glm::value_ptr(shadow));
    glBindTextureUnit(0, mAtlas);
    glBindTextureUnit(1, mTable);
    mLighting.draw(ctx.submitter, cameraCullView(ctx));
    glBindTextureUnit(0, 0);
    glBindTextureUnit(1, 0);
}

void VirtualGL::execute(FrameContext& ctx) {
    const SubmitStats s = DepthLightingFrame::run(
        ctx,
        [&] {
            if (mLight < 0) return;
            markPages(ctx);
            allocatePages();
            renderPages(ctx);
        },
        [&] { renderLighting(ctx); });
    const PageGeometry& g = mCache->geometry();
    const PageCounts& c = mCache->counts();
    mCounters = DepthLightingFrame::counters(s, double(c.rendered) * g.pageSize() * g.pageSize(), {});
    for (auto& kv : c.toCounters()) mCounters.push_back(kv);
}

} // namespace sb
