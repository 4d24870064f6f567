#include "techniques/shadowmap/PcssGL.h"
#include "techniques/shadowmap/FlatLightsGL.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "techniques/ContactShadows.h"
#include "techniques/DepthLightingFrame.h"
#include "techniques/ShadowMapProperties.h"
#include "techniques/shadowmap/DepthPassState.h"
#include "techniques/shadowmap/PoissonDisk.h"

namespace sb {

namespace {
using P = ShadowMapProperties;
// shaders/shadowmap/pcss.frag: uPcssLight[LIGHT_COUNT], uPcssSearch[LIGHT_COUNT], the two kernels.
constexpr GLint kLightLocation = 12;
constexpr GLint kSearchLocation = 16;
constexpr GLint kBlockerKernelLocation = 20; // uBlockerKernel[Pcss::kMaxTaps]
constexpr GLint kFilterKernelLocation =
    kBlockerKernelLocation + Pcss::kMaxTaps;                            // uFilterKernel[Pcss::kMaxTaps]
constexpr GLint kTapsLocation = kFilterKernelLocation + Pcss::kMaxTaps; // uTaps
constexpr GLint kSearchUnit = 0, kCompareUnit = 1;

} // namespace

PcssGL::PcssGL() : GlTechnique(Pcss::declaration()) {}

PcssGL::~PcssGL() {
    if (mSearchSampler) glDeleteSamplers(1, &mSearchSampler);
    if (mCompareSampler) glDeleteSamplers(1, &mCompareSampler);
}

void PcssGL::propertiesApplied() {
    mutableInfo().passes = ContactShadows::passes(properties(), Pcss::declaration().passes);
}

void PcssGL::setScene(const Scene& scene) {
    mLights.setScene(scene, "pcss", properties());
    mCulling.setScene(scene);
}

void PcssGL::createSamplers() {
    if (mSearchSampler) return;
    // Outside the map lies no caster (the light camera is fitted to them): a border depth of 1 makes
    // taps that leave it find no blocker and compare lit.
    const float border[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    glCreateSamplers(1, &mSearchSampler);
    glCreateSamplers(1, &mCompareSampler);
    for (GLuint s : {mSearchSampler, mCompareSampler}) {
        glSamplerParameteri(s, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
        glSamplerParameteri(s, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
        glSamplerParameterfv(s, GL_TEXTURE_BORDER_COLOR, border);
    }
    glSamplerParameteri(mSearchSampler, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(mSearchSampler, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(mSearchSampler, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glSamplerParameteri(mCompareSampler, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glSamplerParameteri(mCompareSampler, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(mCompareSampler, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glSamplerParameteri(mCompareSampler, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
}

void PcssGL::sceneChanged(const Scene& scene, uint32_t) {
    setScene(scene);
    fitLightSizes(scene);
}

void PcssGL::fitLightSizes(const Scene& scene) {
    mParams.clear();
    for (size_t i = 0; i < mLights.size(); ++i)
        mParams.push_back(Pcss::lightParams(scene, scene.lights[i], mLights.viewProj()[i],
                                            float(properties().getFloat(Pcss::kLightSize))));
}

void PcssGL::compile(const CompileContext& ctx) {
    const PropertySet& p = properties();
    const int layers = std::max<int>(1, int(mLights.size()));
    // The texture's own sampling state is unused: both units sample through the sampler objects.
    mMaps.allocate(GL_TEXTURE_2D_ARRAY, int(p.getInt(P::kResolution)), layers, false);
    createSamplers();
    mBlockerKernel = PoissonDisk::generate(int(p.getInt(Pcss::kBlockerTaps)));
    mFilterKernel = PoissonDisk::generate(int(p.getInt(Pcss::kFilterTaps)), Pcss::filterSeed());
    fitLightSizes(ctx.scene);

    Defines base = ctx.submitter.defines();
    mDepthProgram = &ctx.programs.get({"common/depth.vert", "common/depth.frag", ""}, base);
    mContact.compile(p, ctx.programs, base);
    Defines lit = ctx.defines(); // the depth pass has no shadow to apply
    lit["SHADOW_MAP"] = "";
    lit["LIGHT_COUNT"] = std::to_string(layers);
    ContactShadows::addDefines(p, lit);
    setPermutationKey(mDepthProgram->key() + "|" +
                      mLighting.compile(ctx, {"common/scene.vert", "shadowmap/pcss.frag", ""}, lit));
}

void PcssGL::renderDepth(FrameContext& ctx) {
    const PropertySet& p = properties();
    DepthPassState state(mMaps.size(), float(p.getFloat(P::kBiasSlope)), float(p.getFloat(P::kBiasConstant)));
    mDepthProgram->use();
    mCulled = renderFlatDepth(mLights, ctx.submitter, mCulling, mMaps, mKeep);
}

void PcssGL::uploadLightUniforms() const {
    std::vector<glm::vec4> light;
    std::vector<glm::vec4> search;
    for (const LightParams& lp : mParams) {
        light.push_back(Pcss::lightVector(lp));
        search.push_back(Pcss::searchVector(lp));
    }
    if (!light.empty()) {
        glUniform4fv(kLightLocation, GLsizei(light.size()), glm::value_ptr(light[0]));
        glUniform4fv(kSearchLocation, GLsizei(search.size()), glm::value_ptr(search[0]));
    }
    glUniform2i(kTapsLocation, GLint(mBlockerKernel.size()), GLint(mFilterKernel.size()));
    glUniform2fv(kBlockerKernelLocation, GLsizei(mBlockerKernel.size()), glm::value_ptr(mBlockerKernel[0]));
    glUniform2fv(kFilterKernelLocation, GLsizei(mFilterKernel.size()), glm::value_ptr(mFilterKernel[0]));
}

void PcssGL::renderLighting(FrameContext& ctx) {
    ctx.targets.bind();
    mLighting.program().use();
    setFlatShadowMatrices(mLights);
    uploadLightUniforms();
    // One texture, two samplers: raw depths for the blocker search, comparison for the filter.
    glBindTextureUnit(kSearchUnit, mMaps.texture());
    glBindTextureUnit(kCompareUnit, mMaps.texture());
    glBindSampler(kSearchUnit, mSearchSampler);
    glBindSampler(kCompareUnit, mCompareSampler);
    mContact.bind();
    mLighting.draw(ctx.submitter, cameraCullView(ctx));
    mContact.unbind();
    glBindSampler(kSearchUnit, 0);
    glBindSampler(kCompareUnit, 0);
    glBindTextureUnit(kSearchUnit, 0);
    glBindTextureUnit(kCompareUnit, 0);
}

void PcssGL::execute(FrameContext& ctx) {
    const SubmitStats s = DepthLightingFrame::run(
        ctx, [&] { renderDepth(ctx); }, [&] { renderLighting(ctx); }, mContact.prePass(ctx),
        ContactShadows::kPass);
    mCounters = Pcss::counters(s, mMaps.size(), mLights, mCulled, mBlockerKernel.size(), mFilterKernel.size(),
                               mParams);
}

} // namespace sb
