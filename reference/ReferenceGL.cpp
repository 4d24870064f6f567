#include "reference/ReferenceGL.h"

#include <algorithm>

#include "scenes/Motion.h"

namespace sb {

ReferenceGL::ReferenceGL() : GlTechnique(Reference::declaration()) {}

ReferenceGL::~ReferenceGL() {
    releaseTexture();
}

void ReferenceGL::sceneChanged(const Scene& scene, uint32_t changes) {
    if (changes & kCastersMoved) setScene(scene);
}

void ReferenceGL::setScene(const Scene& scene) {
    // Tracer first: it holds a reference to the Embree scene it replaces.
    mTracer.reset();
    mEmbree = std::make_unique<EmbreeScene>(scene);
    mTracer = std::make_unique<ReferenceTracer>(scene, *mEmbree);
    mScene = &scene;
    if (mGBufferRenderer) mGBufferRenderer->setScene(scene);
}

void ReferenceGL::compile(const CompileContext& ctx) {
    mPrograms = &ctx.programs;
    Defines base = ctx.submitter.defines();
    // Compiled here so the JIT cost and any error fall into setup; the renderer finds it cached.
    const Program& gbuffer = ctx.programs.get({"reference/gbuffer.vert", "reference/gbuffer.frag", ""}, base);
    Defines shade = base;
    shade["LIGHT_COUNT"] = std::to_string(std::clamp<int>(int(ctx.scene.lights.size()), 1, kMaxLights));
    addLightingRateDefines(ctx.scene, shade); // shaded as the techniques it is compared with
    mShadeProgram = &ctx.programs.get({"common/scene.vert", "reference/shade.frag", ""}, shade);
    setPermutationKey(gbuffer.key() + "|" + mShadeProgram->key());
}

void ReferenceGL::releaseTexture() {
    if (mVisibilityTexture) glDeleteTextures(1, &mVisibilityTexture);
    mVisibilityTexture = 0;
}

void ReferenceGL::ensureTargets(int width, int height) {
    if (width == mWidth && height == mHeight && mGBufferRenderer) return;
    releaseTexture();
    mGBufferRenderer = std::make_unique<GBufferRenderer>(width, height);
    mGBufferRenderer->setScene(*mScene);
    glCreateTextures(GL_TEXTURE_2D, 1, &mVisibilityTexture);
    glTextureStorage2D(mVisibilityTexture, 1, GL_RGBA32F, width, height);
    glTextureParameteri(mVisibilityTexture, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(mVisibilityTexture, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    mWidth = width;
    mHeight = height;
}

ReferenceTracer::Options ReferenceGL::tracerOptions() const {
    return Reference::tracerOptions(properties());
}

void ReferenceGL::renderGBuffer(FrameContext& ctx) {
    ensureTargets(ctx.targets.width(), ctx.targets.height());
    // proj * view as the frame uniforms compute it (techniques/gl/FrameUniforms.cpp): the same float
    // matrix as the shade pass's uViewProj, so both passes rasterise identically.
    mGBuffer = mGBufferRenderer->render(ctx.submitter, *mPrograms, ctx.proj * ctx.view);
}

void ReferenceGL::trace() {
    const ReferenceTracer::Options options = tracerOptions();
    size_t lights = std::min<size_t>(mScene->lights.size(), kMaxLights);
    mVisibility.assign(lights, {});
    mTraceStats.assign(lights, {});
    for (size_t i = 0; i < lights; ++i)
        mVisibility[i] = mTracer->trace(mGBuffer, int(i), options, &mTraceStats[i]);
}

void ReferenceGL::uploadVisibility() {
    std::vector<float> rgba(size_t(mWidth) * size_t(mHeight) * 4);
    Reference::packVisibility(mVisibility, mWidth, mHeight, false, rgba.data());
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glTextureSubImage2D(mVisibilityTexture, 0, 0, 0, mWidth, mHeight, GL_RGBA, GL_FLOAT, rgba.data());
}

void ReferenceGL::shade(FrameContext& ctx) {
    // The harness cleared depth before execute() and the G-buffer pass drew into its own FBO, so the
    // depth test (LESS) resolves the same visible surface per pixel as the G-buffer did.
    ctx.targets.bind();
    mShadeProgram->use();
    glBindTextureUnit(0, mVisibilityTexture);
    ctx.submitter.draw(DrawSet::All);
    glBindTextureUnit(0, 0);
}

void ReferenceGL::execute(FrameContext& ctx) {
    ctx.passes.begin("gbuffer");
    renderGBuffer(ctx);
    ctx.passes.begin("trace");
    trace();
    uploadVisibility();
    ctx.passes.begin("shade");
    ctx.submitter.resetStats();
    shade(ctx);
    updateCounters(ctx.submitter.stats());
}

void ReferenceGL::updateCounters(const SubmitStats& shadeStats) {
    // Both passes' draws, the G-buffer's counted by its renderer (it may draw without the submitter).
    const SubmitStats& g = mGBufferRenderer->lastStats();
    mCounters = Reference::counters(g + shadeStats, mTraceStats);
}

} // namespace sb
