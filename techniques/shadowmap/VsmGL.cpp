#include "techniques/shadowmap/VsmTechnique.h"

namespace sb {

namespace {
constexpr const char* kResolution = "resolution";
constexpr const char* kBlur = "blur";
constexpr const char* kCull = "cull";
constexpr const char* kReceiverBackground = "receiver_background";
constexpr const char* kMinVariance = "min_variance";
constexpr const char* kBleedReduction = "bleed_reduction";
constexpr GLint kMinVarianceLocation = 40;    // shadowmap/vsm.frag
constexpr GLint kBleedReductionLocation = 41; // ...
/// Nothing in front of the far end of the light's depth range: the moments of d = 1.
constexpr glm::vec4 kNoOccluder{1.0f, 1.0f, 0.0f, 0.0f};

std::vector<PropertyDesc> declareProperties() {
    return {
        integer(kResolution, "1024", 16, 8192, "moment map width and height (texels)"),
        integer(kBlur, "3", 0, SeparableBlur::kMaxWidth,
                "separable Gaussian kernel width in texels (sigma = width / 4; 0 or 1 = no blur)"),
        flag(kReceiverBackground, "true",
             "non-casters drawn behind the casters as the map's background (the farthest per texel): the "
             "filter sees the receiver, not the far plane, beside an occluder's edge"),
        flag(kCull, "true",
             "leave out of each light's map the casters whose shadow cannot reach the view (grown by the "
             "blur's reach)"),
        real(kMinVariance, "1e-06", 0, 0.01,
             "lower bound of the filtered variance (linear depth in [0, 1], squared): against the "
             "bound's numeric acne"),
        real(kBleedReduction, "0.2", 0, 0.99,
             "light-bleeding reduction: linstep(amount, 1, p_max) removes the bound's [0, amount] tail"),
    };
}
} // namespace

VsmTechnique::VsmTechnique()
    : Technique(
          {.name = "vsm",
           .description = "variance shadow maps: filtered moments, Chebyshev's bound in the lighting pass",
           .effects = Effect::HardShadows | Effect::SelfShadowing | Effect::NonPlanarReceivers |
                      Effect::MultipleLights,
           .capabilities = {{"GL 4.5", 4, 5, ""}},
           .passes = {"depth", "blur", "lighting"},
           .properties = declareProperties(),
           .quality = {
               {kResolution, {"256", "512", "1024", "2048", "4096"}},
               {kBlur, {"0", "3", "5", "9"}},
               {kBleedReduction, {"0", "0.2", "0.4", "0.6"}},
           }}) {}

void VsmTechnique::setScene(const Scene& scene) {
    mMaps.setScene(scene);
}

void VsmTechnique::compile(const CompileContext& ctx) {
    const PropertySet& p = properties();
    const int resolution = int(p.getInt(kResolution));
    mMaps.setReceiverBackground(p.getBool(kReceiverBackground));
    mMaps.setViewCull(p.getBool(kCull));
    // The border the filter's reads need: the blur's radius and the bilinear footprint's texel.
    mMaps.fit(ctx.scene, resolution, int(p.getInt(kBlur)) / 2 + 1);
    mMaps.allocate(resolution, GL_RG32F);
    Defines depth = ctx.submitter.defines();
    depth["VSM"] = "";
    mDepthProgram = &ctx.programs.get({"shadowmap/moments.vert", "shadowmap/moments.frag", ""}, depth);
    Defines lit = ctx.defines();
    lit["SHADOW_MAP"] = ""; // common/scene.vert: vShadowCoord[i] = uShadowMatrix[i] * world
    lit["LIGHT_COUNT"] = std::to_string(mMaps.layers());
    mLightingProgram = &ctx.programs.get({"common/scene.vert", "shadowmap/vsm.frag", ""}, lit);
    std::string key = mDepthProgram->key() + "|" + mLightingProgram->key();
    const std::string blur =
        mBlur.compile(ctx.programs, SeparableBlur::Mode::Linear, int(p.getInt(kBlur)), resolution, GL_RG32F);
    if (!blur.empty()) key += "|" + blur;
    setPermutationKey(key);
}

void VsmTechnique::execute(FrameContext& ctx) {
    mCounters = mMaps.renderFrame(ctx, *mDepthProgram, kNoOccluder, mBlur, *mLightingProgram, [&] {
        const PropertySet& p = properties();
        glUniform1f(kMinVarianceLocation, float(p.getFloat(kMinVariance)));
        glUniform1f(kBleedReductionLocation, float(p.getFloat(kBleedReduction)));
    });
}

} // namespace sb
