#include "techniques/shadowmap/EvsmGL.h"

namespace sb {

namespace {
constexpr GLint kMinVarianceLocation = 40;    // shadowmap/evsm.frag
constexpr GLint kBleedReductionLocation = 41; // ...

} // namespace

EvsmGL::EvsmGL() : GlTechnique(Evsm::declaration()) {}

void EvsmGL::setScene(const Scene& scene) {
    mMaps.fits().setScene(scene, properties());
}

void EvsmGL::compile(const CompileContext& ctx) {
    const PropertySet& p = properties();
    const int resolution = int(p.getInt(Evsm::kResolution));
    const GLenum format = Evsm::negativeWarp(p) ? GL_RGBA32F : GL_RG32F;
    mMaps.fits().setReceiverBackground(p.getBool(Evsm::kReceiverBackground));
    mMaps.fits().setViewCull(p.getBool(Evsm::kCull));
    // The border the filter's reads need: the blur's radius and the bilinear footprint's texel.
    mMaps.fits().fit(ctx.scene, resolution, int(p.getInt(Evsm::kBlur)) / 2 + 1);
    mMaps.allocate(resolution, format);
    Defines depth = ctx.submitter.defines();
    Evsm::addDefines(p, depth);
    mDepthProgram = &ctx.programs.get({"shadowmap/moments.vert", "shadowmap/moments.frag", ""}, depth);
    Defines lit = ctx.defines();
    Evsm::addDefines(p, lit);
    lit["SHADOW_MAP"] = ""; // common/scene.vert: vShadowCoord[i] = uShadowMatrix[i] * world
    lit["LIGHT_COUNT"] = std::to_string(mMaps.layers());
    std::string key = mDepthProgram->key() + "|" +
                      mLighting.compile(ctx, {"common/scene.vert", "shadowmap/evsm.frag", ""}, lit);
    const std::string blur = mBlur.compile(ctx.programs, {.kernel = SeparableBlur::Kernel::TexelIntegral,
                                                          .size = int(p.getInt(Evsm::kBlur)),
                                                          .mode = SeparableBlur::Mode::Linear,
                                                          .border = SeparableBlur::Border::ClampToEdge,
                                                          .resolution = resolution,
                                                          .format = format});
    if (!blur.empty()) key += "|" + blur;
    setPermutationKey(key);
}

void EvsmGL::execute(FrameContext& ctx) {
    const PropertySet& p = properties();
    mCounters = mMaps.renderFrame(ctx, *mDepthProgram, Evsm::noOccluder(p), mBlur, mLighting, [&] {
        glUniform1f(kMinVarianceLocation, float(p.getFloat(Evsm::kMinVariance)));
        glUniform1f(kBleedReductionLocation, float(p.getFloat(Evsm::kBleedReduction)));
    });
}

} // namespace sb
