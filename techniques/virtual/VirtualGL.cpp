#include "techniques/virtual/VirtualGL.h"

#include <algorithm>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "core/Error.h"
#include "scenes/Motion.h"
#include "techniques/ContactShadows.h"
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
constexpr GLint kBiasLocation = 16;           // page_depth.frag: (constant, slope)
constexpr GLint kLevelLocation = 17;          // page_depth.frag: the level drawn
constexpr GLint kPageGeometryLocation = 20;   // page_table.glsl: sizes
constexpr GLint kPageLodLocation = 21;        // page_table.glsl: footprint, lod bias
constexpr uint32_t kClearDepth = 0x3f800000u; // floatBitsToUint(1.0): nothing drawn, lit

GLuint r32uiTexture(int width, int height) {
    GLuint t = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &t);
    glTextureStorage2D(t, 1, GL_R32UI, width, height);
    // Integer textures are read with texelFetch; NEAREST keeps them complete.
    glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return t;
}

/// page_table.glsl's uniforms into the program in use.
void setPageUniforms(const PropertySet& p) {
    const Virtual::PageUniforms u = Virtual::pageUniforms(p);
    glUniform4iv(kPageGeometryLocation, 1, glm::value_ptr(u.geometry));
    glUniform4fv(kPageLodLocation, 1, glm::value_ptr(u.lod));
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

void VirtualGL::propertiesApplied() {
    mutableInfo().passes = ContactShadows::passes(properties(), Virtual::declaration().passes);
}

void VirtualGL::setScene(const Scene& scene) {
    mMaps.setScene(scene, properties());
    mCulling.setScene(scene);
}

void VirtualGL::sceneChanged(const Scene& scene, uint32_t changes) {
    if (changes & kCastersMoved) mCulling.instancesMoved(scene);
    mMaps.sceneChanged(scene, changes);
}

void VirtualGL::compile(const CompileContext& ctx) {
    release();
    const PropertySet& p = properties();
    if (Virtual::sparse(p))
        throw Error("virtual: path=sparse binds pages of a sparse-resident Vulkan image; the GL form has the "
                    "atomic path only (path=atomic, or --api vulkan)",
                    ExitCode::Unsupported);
    const PageGeometry& g = mMaps.geometry();
    requireLimit(GL_MAX_VIEWPORT_DIMS, "GL_MAX_VIEWPORT_DIMS", g.virtualResolution());
    requireLimit(GL_MAX_FRAMEBUFFER_WIDTH, "GL_MAX_FRAMEBUFFER_WIDTH", g.virtualResolution());
    requireLimit(GL_MAX_FRAMEBUFFER_HEIGHT, "GL_MAX_FRAMEBUFFER_HEIGHT", g.virtualResolution());
    requireLimit(GL_MAX_TEXTURE_SIZE, "GL_MAX_TEXTURE_SIZE", g.atlasResolution());
    mRequests = r32uiTexture(g.pagesPerSide(), g.tableRows());
    mTable = r32uiTexture(g.pagesPerSide(), g.tableRows());
    mAtlas = r32uiTexture(g.atlasResolution(), g.atlasResolution());
    const uint32_t zero = 0;
    glClearTexImage(mTable, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    glCreateFramebuffers(1, &mEmptyFbo);
    glNamedFramebufferParameteri(mEmptyFbo, GL_FRAMEBUFFER_DEFAULT_WIDTH, g.virtualResolution());
    glNamedFramebufferParameteri(mEmptyFbo, GL_FRAMEBUFFER_DEFAULT_HEIGHT, g.virtualResolution());

    mMarkProgram = &ctx.programs.get({"common/scene.vert", "virtual/mark.frag", ""}, ctx.defines());
    mPageProgram =
        &ctx.programs.get({"common/depth.vert", "virtual/page_depth.frag", ""}, ctx.submitter.defines());
    mContact.compile(p, ctx.programs, ctx.submitter.defines());
    Defines lit = ctx.defines();
    ContactShadows::addDefines(p, lit);
    lit["LIGHT_COUNT"] = std::to_string(std::max<size_t>(1, ctx.scene.lights.size()));
    lit["MAPPED_LIGHT"] = std::to_string(mMaps.light());
    setPermutationKey(mMarkProgram->key() + "|" + mPageProgram->key() + "|" +
                      mLighting.compile(ctx, {"common/scene.vert", "virtual/lighting.frag", ""}, lit));
}

void VirtualGL::markPages(FrameContext& ctx) {
    const uint32_t zero = 0;
    glClearTexImage(mRequests, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    ctx.targets.bind();
    mMarkProgram->use();
    setPageUniforms(properties());
    const glm::mat4 shadow = FlatLightFits::textureBias() * mMaps.lightViewProj();
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
    const PageGeometry& g = mMaps.geometry();
    mWords.resize(size_t(g.pagesPerSide()) * size_t(g.tableRows()));
    glGetTextureImage(mRequests, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, GLsizei(mWords.size() * 4),
                      mWords.data());
    // The marks are read before allocate() writes the table into the same words.
    const std::vector<uint32_t> marks = mWords;
    mMaps.allocate(marks.data(), properties().getBool(Virtual::kCache), mWords);
    glTextureSubImage2D(mTable, 0, 0, 0, g.pagesPerSide(), g.tableRows(), GL_RED_INTEGER, GL_UNSIGNED_INT,
                        mWords.data());
    for (uint32_t page : mMaps.cache().renderList()) {
        const glm::ivec2 o = g.atlasOrigin(mMaps.cache().table().slot(page));
        glClearTexSubImage(mAtlas, 0, o.x, o.y, 0, g.pageSize(), g.pageSize(), 1, GL_RED_INTEGER,
                           GL_UNSIGNED_INT, &kClearDepth);
    }
}

void VirtualGL::renderPages(FrameContext& ctx) {
    const PageGeometry& g = mMaps.geometry();
    const PropertySet& p = properties();
    glBindFramebuffer(GL_FRAMEBUFFER, mEmptyFbo);
    glEnable(GL_SCISSOR_TEST);
    glEnable(GL_DEPTH_CLAMP); // casters nearer the light than the fit's near side still shadow
    mPageProgram->use();
    setPageUniforms(p);
    glUniformMatrix4fv(kLightViewProjLocation, 1, GL_FALSE, glm::value_ptr(mMaps.lightViewProj()));
    glUniform2f(kBiasLocation, float(p.getFloat(P::kBiasConstant)), float(p.getFloat(P::kBiasSlope)));
    glBindImageTexture(0, mAtlas, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
    glBindTextureUnit(1, mTable);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    int viewportLevel = -1;
    for (const PageRun& run : mMaps.runs()) {
        if (run.level != viewportLevel) {
            viewportLevel = run.level;
            glViewport(0, 0, g.levelResolution(run.level), g.levelResolution(run.level));
            glUniform1i(kLevelLocation, run.level);
        }
        glScissor(run.first.x * g.pageSize(), run.first.y * g.pageSize(), run.count * g.pageSize(),
                  g.pageSize());
        mCulling.cull(run.crop(g) * mMaps.lightViewProj(), DrawSet::Casters, CullPlanes::SidesAndFar, mKeep);
        ctx.submitter.drawCulled(DrawSet::Casters, {mMaps.lightViewProj(), true}, mKeep);
    }
    glDisable(GL_DEPTH_CLAMP);
    glDisable(GL_SCISSOR_TEST);
    glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
    glBindTextureUnit(1, 0);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT); // the atomics before the lighting pass's fetches
    mMaps.rendered();
}

void VirtualGL::renderLighting(FrameContext& ctx) {
    ctx.targets.bind();
    mLighting.program().use();
    setPageUniforms(properties());
    const glm::mat4 shadow = FlatLightFits::textureBias() * mMaps.lightViewProj();
    glUniformMatrix4fv(kLightMatrixLocation, 1, GL_FALSE, glm::value_ptr(shadow));
    glBindTextureUnit(0, mAtlas);
    glBindTextureUnit(1, mTable);
    mContact.bind();
    mLighting.draw(ctx.submitter, cameraCullView(ctx));
    mContact.unbind();
    glBindTextureUnit(0, 0);
    glBindTextureUnit(1, 0);
}

void VirtualGL::execute(FrameContext& ctx) {
    mMaps.texels().setCamera(ctx.proj * ctx.view, {ctx.targets.width(), ctx.targets.height()});
    const SubmitStats s = DepthLightingFrame::run(
        ctx,
        [&] {
            if (mMaps.light() < 0) return;
            markPages(ctx);
            allocatePages();
            renderPages(ctx);
        },
        [&] { renderLighting(ctx); }, mContact.prePass(ctx), ContactShadows::kPass);
    mCounters = mMaps.counters(s);
}

} // namespace sb
