#include "techniques/shadowmap/EsmTechnique.h"

namespace sb {

namespace {
constexpr const char* kResolution = "resolution";
constexpr const char* kBlur = "blur";
constexpr const char* kCull = "cull";
constexpr const char* kReceiverBackground = "receiver_background";
constexpr const char* kExponent = "exponent";
constexpr GLint kExponentLocation = 40; // shadowmap/esm.frag
/// Nothing in front of the far end of the light's depth range: d = 1.
constexpr glm::vec4 kNoOccluder{1.0f, 0.0f, 0.0f, 0.0f};

std::vector<PropertyDesc> declareProperties() {
    return {
        integer(kResolution, "1024", 16, 8192, "depth map width and height (texels)"),
        integer(
            kBlur, "3", 0, SeparableBlur::kMaxWidth,
            "separable Gaussian kernel width in texels, over exp(c d) (sigma = width / 4; 0 or 1 = no blur)"),
        flag(kReceiverBackground, "true",
             "non-casters drawn behind the casters as the map's background (the farthest per texel): the "
             "filter sees the receiver, not the far plane, beside an occluder's edge"),
        flag(kCull, "true",
             "leave out of each light's map the casters whose shadow cannot reach the view (grown by the "
             "blur's reach)"),
        real(kExponent, "160", 1, EsmTechnique::kMaxExponent,
             "c of exp(c (d_occ - t)) over linear depth in [0, 1]: larger is sharper towards contact"),
    };
}
} // namespace

EsmTechnique::EsmTechnique()
    : Technique({.name = "esm",
                 .description = "exponential shadow maps: filtered exp(c d), filtered in log space",
                 .effects = Effect::HardShadows | Effect::SelfShadowing | Effect::NonPlanarReceivers |
                            Effect::MultipleLights,
                 .capabilities = {{"GL 4.5", 4, 5, ""}},
                 .passes = {"depth", "blur", "lighting"},
                 .properties = declareProperties(),
                 .quality = {
                     {kResolution, {"256", "512", "1024", "2048", "4096"}},
                     {kBlur, {"0", "3", "5", "9"}},
                     {kExponent, {"10", "40", "80", "160", "500"}},
                 }}) {}

void EsmTechnique::setScene(const Scene& scene) {
    mMaps.setScene(scene);
}

void EsmTechnique::compile(const CompileContext& ctx) {
    const PropertySet& p = properties();
    const int resolution = int(p.getInt(kResolution));
    mMaps.setReceiverBackground(p.getBool(kReceiverBackground));
    mMaps.setViewCull(p.getBool(kCull));
    // The border the filter's reads need: the blur's radius and the bilinear footprint's texel.
    mMaps.fit(ctx.scene, resolution, int(p.getInt(kBlur)) / 2 + 1);
    mMaps.allocate(resolution, GL_R32F);
    mDepthProgram =
        &ctx.programs.get({"shadowmap/moments.vert", "shadowmap/moments.frag", ""}, ctx.submitter.defines());
    Defines lit = ctx.defines();
    lit["SHADOW_MAP"] = ""; // common/scene.vert: vShadowCoord[i] = uShadowMatrix[i] * world
    lit["LIGHT_COUNT"] = std::to_string(mMaps.layers());
    mLightingProgram = &ctx.programs.get({"common/scene.vert", "shadowmap/esm.frag", ""}, lit);
    std::string key = mDepthProgram->key() + "|" + mLightingProgram->key();
    const std::string blur =
        mBlur.compile(ctx.programs, SeparableBlur::Mode::LogSpace, int(p.getInt(kBlur)), resolution, GL_R32F);
    mBlur.setExponent(float(p.getFloat(kExponent)));
    if (!blur.empty()) key += "|" + blur;
    setPermutationKey(key);
}

void EsmTechnique::execute(FrameContext& ctx) {
    mCounters = mMaps.renderFrame(ctx, *mDepthProgram, kNoOccluder, mBlur, *mLightingProgram, [&] {
        glUniform1f(kExponentLocation, float(properties().getFloat(kExponent)));
    });
}

} // namespace sb
