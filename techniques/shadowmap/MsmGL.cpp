#include "techniques/shadowmap/MsmGL.h"

namespace sb {

namespace {
constexpr GLint kMomentBiasLocation = 40;     // shadowmap/msm.frag
constexpr GLint kBleedReductionLocation = 41; // ...

} // namespace

MsmGL::MsmGL() : GlTechnique(Msm::declaration()) {}

void MsmGL::setScene(const Scene& scene) {
    mMaps.fits().setScene(scene, properties());
}

void MsmGL::compile(const CompileContext& ctx) {
    const PropertySet& p = properties();
    const int resolution = int(p.getInt(Msm::kResolution));
    const GLenum format = Msm::quantized(p) ? GL_RGBA16 : GL_RGBA32F;
    mMaps.fits().setReceiverBackground(p.getBool(Msm::kReceiverBackground));
    mMaps.fits().setViewCull(p.getBool(Msm::kCull));
    // The border the filter's reads need: the blur's radius and the bilinear footprint's texel.
    mMaps.fits().fit(ctx.scene, resolution, int(p.getInt(Msm::kBlur)) / 2 + 1);
    mMaps.allocate(resolution, format);
    Defines depth = ctx.submitter.defines();
    Msm::addDefines(p, depth);
    mDepthProgram = &ctx.programs.get({"shadowmap/moments.vert", "shadowmap/moments.frag", ""}, depth);
    Defines lit = ctx.defines();
    Msm::addDefines(p, lit);
    lit["SHADOW_MAP"] = ""; // common/scene.vert: vShadowCoord[i] = uShadowMatrix[i] * world
    lit["LIGHT_COUNT"] = std::to_string(mMaps.layers());
    std::string key = mDepthProgram->key() + "|" +
                      mLighting.compile(ctx, {"common/scene.vert", "shadowmap/msm.frag", ""}, lit);
    const std::string blur = mBlur.compile(ctx.programs, {.kernel = SeparableBlur::Kernel::TexelIntegral,
                                                          .size = int(p.getInt(Msm::kBlur)),
                                                          .mode = SeparableBlur::Mode::Linear,
                                                          .border = SeparableBlur::Border::ClampToEdge,
                                                          .resolution = resolution,
                                                          .format = format});
    if (!blur.empty()) key += "|" + blur;
    setPermutationKey(key);
}

void MsmGL::execute(FrameContext& ctx) {
    const PropertySet& p = properties();
    mCounters = mMaps.renderFrame(ctx, *mDepthProgram, Msm::noOccluder(p), mBlur, mLighting, [&] {
        glUniform1f(kMomentBiasLocation, float(p.getFloat(Msm::kMomentBias)));
        glUniform1f(kBleedReductionLocation, float(p.getFloat(Msm::kBleedReduction)));
    });
}

} // namespace sb
