#include "techniques/shadowmap/VsmGL.h"

namespace sb {

namespace {
constexpr GLint kMinVarianceLocation = 40;    // shadowmap/vsm.frag
constexpr GLint kBleedReductionLocation = 41; // ...
/// Nothing in front of the far end of the light's depth range: the moments of d = 1.
constexpr glm::vec4 kNoOccluder{1.0f, 1.0f, 0.0f, 0.0f};

} // namespace

VsmGL::VsmGL() : GlTechnique(Vsm::declaration()) {}

void VsmGL::setScene(const Scene& scene) {
    mMaps.fits().setScene(scene, properties());
}

void VsmGL::compile(const CompileContext& ctx) {
    const PropertySet& p = properties();
    const int resolution = int(p.getInt(Vsm::kResolution));
    mMaps.fits().setReceiverBackground(p.getBool(Vsm::kReceiverBackground));
    mMaps.fits().setViewCull(p.getBool(Vsm::kCull));
    // The border the filter's reads need: the blur's radius and the bilinear footprint's texel.
    mMaps.fits().fit(ctx.scene, resolution, int(p.getInt(Vsm::kBlur)) / 2 + 1);
    mMaps.allocate(resolution, GL_RG32F);
    Defines depth = ctx.submitter.defines();
    depth["VSM"] = "";
    mDepthProgram = &ctx.programs.get({"shadowmap/moments.vert", "shadowmap/moments.frag", ""}, depth);
    Defines lit = ctx.defines();
    lit["SHADOW_MAP"] = ""; // common/scene.vert: vShadowCoord[i] = uShadowMatrix[i] * world
    lit["LIGHT_COUNT"] = std::to_string(mMaps.layers());
    std::string key = mDepthProgram->key() + "|" +
                      mLighting.compile(ctx, {"common/scene.vert", "shadowmap/vsm.frag", ""}, lit);
    const std::string blur = mBlur.compile(ctx.programs, {.kernel = SeparableBlur::Kernel::TexelIntegral,
                                                          .size = int(p.getInt(Vsm::kBlur)),
                                                          .mode = SeparableBlur::Mode::Linear,
                                                          .border = SeparableBlur::Border::ClampToEdge,
                                                          .resolution = resolution,
                                                          .format = GL_RG32F});
    if (!blur.empty()) key += "|" + blur;
    setPermutationKey(key);
}

void VsmGL::execute(FrameContext& ctx) {
    mCounters = mMaps.renderFrame(ctx, *mDepthProgram, kNoOccluder, mBlur, mLighting, [&] {
        const PropertySet& p = properties();
        glUniform1f(kMinVarianceLocation, float(p.getFloat(Vsm::kMinVariance)));
        glUniform1f(kBleedReductionLocation, float(p.getFloat(Vsm::kBleedReduction)));
    });
}

} // namespace sb
