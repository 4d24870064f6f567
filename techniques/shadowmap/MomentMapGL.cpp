#include "techniques/shadowmap/MomentMapGL.h"

#include "techniques/ContactShadows.h"

namespace sb {

namespace {

/// The first of the lighting pass's parameter locations (shadowmap/vsm.frag, esm.frag, evsm.frag,
/// msm.frag: 40, 41).
constexpr GLint kFirstParamLocation = 40;

GLenum glFormat(MomentMapKind::Format f) {
    switch (f) {
    case MomentMapKind::Format::R32F:
        return GL_R32F;
    case MomentMapKind::Format::RG32F:
        return GL_RG32F;
    case MomentMapKind::Format::RGBA16Unorm:
        return GL_RGBA16;
    case MomentMapKind::Format::RGBA32F:
        return GL_RGBA32F;
    }
    return GL_RGBA32F;
}

} // namespace

MomentMapGL::MomentMapGL(const MomentMapKind& kind)
    : GlTechnique(kind.declaration()), mKind(kind), mMaps(kind.declaration().name) {}

void MomentMapGL::propertiesApplied() {
    mutableInfo().passes = ContactShadows::passes(properties(), mKind.declaration().passes);
}

void MomentMapGL::setScene(const Scene& scene) {
    mMaps.fits().setScene(scene, properties());
}

void MomentMapGL::compile(const CompileContext& ctx) {
    const PropertySet& p = properties();
    const int resolution = int(p.getInt(MomentMapKind::kResolution));
    const GLenum format = glFormat(mKind.format(p));
    mMaps.fits().setReceiverBackground(p.getBool(MomentMapKind::kReceiverBackground));
    mMaps.fits().setViewCull(p.getBool(MomentMapKind::kCull));
    // The border the filter's reads need: the blur's radius and the bilinear footprint's texel.
    mMaps.fits().fit(ctx.scene, resolution, int(p.getInt(MomentMapKind::kBlur)) / 2 + 1);
    mMaps.allocate(resolution, format);
    Defines depth = ctx.submitter.defines();
    mKind.depthDefines(p, depth);
    mDepthProgram = &ctx.programs.get({"shadowmap/moments.vert", "shadowmap/moments.frag", ""}, depth);
    mContact.compile(p, ctx.programs, ctx.submitter.defines());
    Defines lit = ctx.defines();
    mKind.lightingDefines(p, lit);
    ContactShadows::addDefines(p, lit);
    lit["SHADOW_MAP"] = ""; // common/scene.vert: vShadowCoord[i] = uShadowMatrix[i] * world
    lit["LIGHT_COUNT"] = std::to_string(mMaps.layers());
    std::string key = mDepthProgram->key() + "|" +
                      mLighting.compile(ctx, {"common/scene.vert", mKind.lightingFragment, ""}, lit);
    const float exponent = mKind.logSpaceExponent(p);
    const std::string blur = mBlur.compile(
        ctx.programs, {.kernel = SeparableBlur::Kernel::TexelIntegral,
                       .size = int(p.getInt(MomentMapKind::kBlur)),
                       .mode = exponent > 0.0f ? SeparableBlur::Mode::LogSpace : SeparableBlur::Mode::Linear,
                       .border = SeparableBlur::Border::ClampToEdge,
                       .resolution = resolution,
                       .format = format});
    if (exponent > 0.0f) mBlur.setExponent(exponent);
    if (!blur.empty()) key += "|" + blur;
    setPermutationKey(key);
}

void MomentMapGL::execute(FrameContext& ctx) {
    const std::vector<float> params = mKind.params(properties());
    mCounters = mMaps.renderFrame(
        ctx, *mDepthProgram, mKind.noOccluder(properties()), mBlur, mLighting,
        [&] {
            for (size_t i = 0; i < params.size(); ++i) glUniform1f(kFirstParamLocation + GLint(i), params[i]);
        },
        mContact);
}

} // namespace sb
