#include "techniques/shadowmap/ParaboloidGL.h"
#include "techniques/shadowmap/OmniLightsGL.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/type_ptr.hpp>

#include "techniques/ContactShadows.h"
#include "techniques/DepthLightingFrame.h"
#include "techniques/ShadowMapProperties.h"
#include "techniques/shadowmap/DepthPassState.h"

namespace sb {

namespace {
using P = ShadowMapProperties;
constexpr GLint kLightLocation = 8;      // shadowmap/paraboloid_depth.vert: position, hemisphere
constexpr GLint kNearFarLocation = 12;   // shadowmap/paraboloid_depth.vert
constexpr GLint kMaxAngleLocation = 13;  // shadowmap/paraboloid_split.geom
constexpr GLint kBeyondRimLocation = 14; // both depth stages
constexpr GLuint kMapUnit = 0;           // shadowmap/omni_lighting.glsl, paraboloid_lighting.frag

} // namespace

ParaboloidGL::ParaboloidGL() : GlTechnique(Paraboloid::declaration()) {}

void ParaboloidGL::propertiesApplied() {
    mutableInfo().passes = ContactShadows::passes(properties(), Paraboloid::declaration().passes);
}

void ParaboloidGL::setScene(const Scene& scene) {
    mLights.setScene(scene, OmniShape::Paraboloid, int(properties().getInt(P::kResolution)));
    mCulling.setScene(scene);
    mOmniCulling.setScene(scene);
    mSplitting.setScene(scene);
}

void ParaboloidGL::compile(const CompileContext& ctx) {
    const PropertySet& p = properties();
    mMaps.allocate(GL_TEXTURE_2D_ARRAY, int(p.getInt(P::kResolution)), flatBase() + mLights.flatCount(),
                   false);
    const Defines base = ctx.submitter.defines();
    mFlatDepth = &ctx.programs.get({"common/depth.vert", "common/depth.frag", ""}, base);
    mContact.compile(p, ctx.programs, base);
    mParaboloidDepth = &ctx.programs.get({"shadowmap/paraboloid_depth.vert", "common/depth.frag", ""}, base);
    // Compiled whether or not `split` uses it: the sources compile() selects stay the same for both
    // values, so the knob adds no shader permutation to build or test.
    mSplitDepth = &ctx.programs.get(
        {"shadowmap/cube_depth.vert", "common/depth.frag", "shadowmap/paraboloid_split.geom"}, base);
    mSplit = p.getBool(Paraboloid::kSplit);
    mMaxSegmentAngle = ParaboloidSplitting::maxSegmentAngle(int(p.getInt(P::kResolution)));
    mBeyondRim = Paraboloid::beyondRim(int(p.getInt(P::kResolution)), int(p.getInt(P::kPcf)));
    // The depth passes have no shadow to apply: only the lighting pass takes the scene's exceptions.
    const Defines lit = Paraboloid::lightingDefines(ctx.defines(), p, mLights);
    const std::string litKey =
        mLighting.compile(ctx, {"common/scene.vert", "shadowmap/paraboloid_lighting.frag", ""}, lit);
    setPermutationKey(mFlatDepth->key() + "|" + mParaboloidDepth->key() + "|" + mSplitDepth->key() + "|" +
                      litKey);
}

// The depth passes draw both faces: the paraboloid warp in the vertex stage is not a linear projection,
// so a closed caster's back faces may cover texels its front faces miss (scenes/BackFaceCulling.h).
void ParaboloidGL::drawHemisphere(FrameContext& ctx, const glm::vec4& light) {
    if (mSplit &&
        mSplitting.partition(glm::vec3(light), mMaxSegmentAngle, mKeep, mKeepPlain, mKeepSplit) > 0) {
        mSplitDepth->use();
        glUniform4fv(kLightLocation, 1, glm::value_ptr(light));
        glUniform1f(kMaxAngleLocation, mMaxSegmentAngle);
        ctx.submitter.draw(DrawSet::Casters, mKeepSplit);
        mSplitDrawn += size_t(std::count(mKeepSplit.begin(), mKeepSplit.end(), uint8_t(1)));
        if (std::find(mKeepPlain.begin(), mKeepPlain.end(), uint8_t(1)) == mKeepPlain.end()) return;
        mParaboloidDepth->use();
        glUniform4fv(kLightLocation, 1, glm::value_ptr(light));
        ctx.submitter.draw(DrawSet::Casters, mKeepPlain);
        return;
    }
    mParaboloidDepth->use();
    glUniform4fv(kLightLocation, 1, glm::value_ptr(light));
    ctx.submitter.draw(DrawSet::Casters, mKeep);
}

void ParaboloidGL::renderHemispheres(FrameContext& ctx) {
    glEnable(GL_CLIP_DISTANCE0);
    for (const OmniLight& o : mLights.lights()) {
        if (o.kind != OmniMapKind::Omni) continue;
        for (const Program* program : {mParaboloidDepth, mSplitDepth}) {
            program->use();
            glUniform2f(kNearFarLocation, o.point.nearZ, o.point.farZ);
            glUniform1f(kBeyondRimLocation, mBeyondRim);
        }
        for (int half = 0; half < 2; ++half) {
            mMaps.beginLayer(2 * o.index + half);
            const size_t kept = mOmniCulling.cullHemisphere(o.point.position, o.point.farZ,
                                                            Paraboloid::hemisphereAxis(half), mKeep);
            mCulled += mOmniCulling.casters() - kept;
            if (kept == 0) continue; // the cleared half is the answer: nothing casts into it
            drawHemisphere(ctx, glm::vec4(o.point.position, float(half)));
            ++mHemispheresRendered;
        }
    }
    glDisable(GL_CLIP_DISTANCE0);
}

void ParaboloidGL::renderDepth(FrameContext& ctx) {
    const PropertySet& p = properties();
    mCulled = 0;
    mSplitDrawn = 0;
    mHemispheresRendered = 0;
    if (mMaps.empty()) return; // no light casts: no depth work at all
    DepthPassState state(mMaps.size(), float(p.getFloat(P::kBiasSlope)), float(p.getFloat(P::kBiasConstant)));
    mCulled += renderOmniFlatMaps(mLights, ctx.submitter, mCulling, *mFlatDepth, mMaps, flatBase(), mKeep);
    renderHemispheres(ctx);
}

void ParaboloidGL::renderLighting(FrameContext& ctx) {
    ctx.targets.bind();
    mLighting.program().use();
    setOmniLightingUniforms(mLights, flatBase(), 2);
    if (!mMaps.empty()) glBindTextureUnit(kMapUnit, mMaps.texture());
    mContact.bind();
    mLighting.draw(ctx.submitter, cameraCullView(ctx));
    mContact.unbind();
    glBindTextureUnit(kMapUnit, 0);
}

void ParaboloidGL::execute(FrameContext& ctx) {
    const SubmitStats s = DepthLightingFrame::run(
        ctx, [&] { renderDepth(ctx); }, [&] { renderLighting(ctx); }, mContact.prePass(ctx),
        ContactShadows::kPass);
    mCounters = Paraboloid::counters(s, mMaps.size(), mMaps.layers(), mLights, mHemispheresRendered, mCulled,
                                     mSplitDrawn);
}

} // namespace sb
