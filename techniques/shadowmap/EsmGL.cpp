#include "techniques/shadowmap/EsmGL.h"

namespace sb {

namespace {
constexpr GLint kExponentLocation = 40; // shadowmap/esm.frag
/// Nothing in front of the far end of the light's depth range: d = 1.
constexpr glm::vec4 kNoOccluder{1.0f, 0.0f, 0.0f, 0.0f};

} // namespace

EsmGL::EsmGL() : GlTechnique(Esm::declaration()) {}

void EsmGL::setScene(const Scene& scene) {
    mMaps.fits().setScene(scene, properties());
}

void EsmGL::compile(const CompileContext& ctx) {
    const PropertySet& p = properties();
    const int resolution = int(p.getInt(Esm::kResolution));
    mMaps.fits().setReceiverBackground(p.getBool(Esm::kReceiverBackground));
    mMaps.fits().setViewCull(p.getBool(Esm::kCull));
    // The border the filter's reads need: the blur's radius and the bilinear footprint's texel.
    mMaps.fits().fit(ctx.scene, resolution, int(p.getInt(Esm::kBlur)) / 2 + 1);
    mMaps.allocate(resolution, GL_R32F);
    mDepthProgram =
        &ctx.programs.get({"shadowmap/moments.vert", "shadowmap/moments.frag", ""}, ctx.submitter.defines());
    Defines lit = ctx.defines();
    lit["SHADOW_MAP"] = ""; // common/scene.vert: vShadowCoord[i] = uShadowMatrix[i] * world
    lit["LIGHT_COUNT"] = std::to_string(mMaps.layers());
    std::string key = mDepthProgram->key() + "|" +
                      mLighting.compile(ctx, {"common/scene.vert", "shadowmap/esm.frag", ""}, lit);
    const std::string blur = mBlur.compile(ctx.programs, {.kernel = SeparableBlur::Kernel::TexelIntegral,
                                                          .size = int(p.getInt(Esm::kBlur)),
                                                          .mode = SeparableBlur::Mode::LogSpace,
                                                          .border = SeparableBlur::Border::ClampToEdge,
                                                          .resolution = resolution,
                                                          .format = GL_R32F});
    mBlur.setExponent(float(p.getFloat(Esm::kExponent)));
    if (!blur.empty()) key += "|" + blur;
    setPermutationKey(key);
}

void EsmGL::execute(FrameContext& ctx) {
    mCounters = mMaps.renderFrame(ctx, *mDepthProgram, kNoOccluder, mBlur, mLighting, [&] {
        glUniform1f(kExponentLocation, float(properties().getFloat(Esm::kExponent)));
    });
}

} // namespace sb
