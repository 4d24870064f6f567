#include "techniques/shadowmap/CascadedGL.h"

#include <glm/gtc/type_ptr.hpp>

#include "techniques/ContactShadows.h"
#include "techniques/DepthLightingFrame.h"
#include "techniques/ShadowMapProperties.h"
#include "techniques/shadowmap/DepthPassState.h"

namespace sb {

namespace {
using P = ShadowMapProperties;
// Uniform locations: common/depth.vert's light matrix, and shadowmap/cascaded_lighting.frag's.
constexpr GLint kLightMatrixLocation = 8;
constexpr GLint kSplitFarLocation = 10;
constexpr GLint kBandStartLocation = 11;
constexpr GLint kBandScaleLocation = 12;
constexpr GLint kEmptySlotsLocation = 15;
constexpr GLint kSlotMatrixLocation = 16; // SLOT_COUNT (at most 16) locations
constexpr GLint kSlotLayerLocation = 32;  // likewise

} // namespace

CascadedGL::CascadedGL() : GlTechnique(Cascaded::declaration()) {}

void CascadedGL::propertiesApplied() {
    mutableInfo().passes = Cascaded::passes(properties());
}

void CascadedGL::setScene(const Scene& scene) {
    mPlan.setScene(scene, int(properties().getInt(Cascaded::kCascades)));
    mRange.reset();
}

void CascadedGL::compile(const CompileContext& ctx) {
    const PropertySet& p = properties();
    mMaps.allocate(GL_TEXTURE_2D_ARRAY, int(p.getInt(P::kResolution)), mPlan.slotCount(), false);
    Defines base = ctx.submitter.defines();
    mDepthProgram = &ctx.programs.get({"common/depth.vert", "common/depth.frag", ""}, base);
    if (Cascaded::viewDepth(p)) mViewDepth.compile(ctx.programs, base);
    if (Cascaded::sampleDistribution(p)) mRange.compile(ctx.programs);
    // The depth pass has no shadow to apply: only the lighting pass takes the scene's exceptions.
    const Defines lit = mPlan.lightingDefines(ctx.defines(), p);
    setPermutationKey(
        mDepthProgram->key() + "|" +
        mLighting.compile(ctx, {"common/scene.vert", "shadowmap/cascaded_lighting.frag", ""}, lit));
}

void CascadedGL::renderDepth(FrameContext& ctx) {
    const PropertySet& p = properties();
    DepthPassState state(mMaps.size(), float(p.getFloat(P::kBiasSlope)), float(p.getFloat(P::kBiasConstant)));
    // Casters nearer the light than a box's near side are not culled (SidesAndFar); clamping keeps any
    // that rounding puts in front of it in the map ("pancaking").
    glEnable(GL_DEPTH_CLAMP);
    mDepthProgram->use();
    mPlan.planDepth(mKeep, [&](size_t slot) {
        mMaps.beginLayer(int(slot));
        glUniformMatrix4fv(kLightMatrixLocation, 1, GL_FALSE, glm::value_ptr(mPlan.slotViewProj()[slot]));
        // Clamped depth: a near side cutting a caster does not open it.
        ctx.submitter.drawCulled(DrawSet::Casters, {mPlan.slotViewProj()[slot], true}, mKeep);
    });
    glDisable(GL_DEPTH_CLAMP);
}

void CascadedGL::renderLighting(FrameContext& ctx) {
    ctx.targets.bind();
    mLighting.program().use();
    const CascadedMaps::SplitValues v = mPlan.splitValues(properties());
    glUniform4fv(kSplitFarLocation, 1, glm::value_ptr(v.splitFar));
    glUniform4fv(kBandStartLocation, 1, glm::value_ptr(v.bandStart));
    glUniform4fv(kBandScaleLocation, 1, glm::value_ptr(v.bandScale));
    glUniform1ui(kEmptySlotsLocation, mPlan.emptySlots());
    glUniformMatrix4fv(kSlotMatrixLocation, GLsizei(mPlan.slotShadow().size()), GL_FALSE,
                       glm::value_ptr(mPlan.slotShadow()[0]));
    glUniform1iv(kSlotLayerLocation, GLsizei(mPlan.slotLayer().size()), mPlan.slotLayer().data());
    glBindTextureUnit(0, mMaps.texture());
    const bool contact = ContactShadows::enabled(properties());
    if (contact) mViewDepth.bindForLighting(ContactShadows::block(properties()));
    mLighting.draw(ctx.submitter, cameraCullView(ctx));
    if (contact) ViewDepthGL::unbindForLighting();
    glBindTextureUnit(0, 0);
}

void CascadedGL::execute(FrameContext& ctx) {
    const PropertySet& p = properties();
    glm::vec2 samples(1.0f, 0.0f); // fit=sdsm: the reduction's view-depth interval
    // The view depth pre-pass, once for both readers: fit=sdsm's reduction and contact=on's march.
    std::function<void()> viewDepth;
    if (Cascaded::viewDepth(p))
        viewDepth = [&] {
            mViewDepth.render(ctx);
            if (Cascaded::sampleDistribution(p)) samples = mRange.run(mViewDepth);
        };
    const SubmitStats s = DepthLightingFrame::run(
        ctx,
        [&] {
            mPlan.fit(ctx.view, ctx.proj, properties(), mMaps.size(), samples);
            renderDepth(ctx);
        },
        [&] { renderLighting(ctx); }, viewDepth, Cascaded::viewDepthPass(p));
    mCounters = mPlan.counters(s, mMaps.size(), ctx.scene, properties());
}

} // namespace sb
