#include "techniques/shadowmap/CascadedGL.h"

#include <algorithm>
#include <cfloat>
#include <cstring>

#include <glm/gtc/type_ptr.hpp>

#include "scenes/LightFit.h"
#include "scenes/Math.h"
#include "scenes/ShadowWork.h"
#include "techniques/PointLightRefusal.h"
#include "techniques/shadowmap/CascadeSplits.h"
#include "techniques/shadowmap/DepthLightingFrame.h"
#include "techniques/shadowmap/DepthPassState.h"
#include "techniques/shadowmap/FlatLightFits.h"
#include "techniques/shadowmap/ShadowMapProperties.h"

namespace sb {

namespace {
using P = ShadowMapProperties;
// Uniform locations: shadowmap/depth.vert's light matrix, and shadowmap/cascaded_lighting.frag's.
constexpr GLint kLightMatrixLocation = 8;
constexpr GLint kSplitFarLocation = 10;
constexpr GLint kBandStartLocation = 11;
constexpr GLint kBandScaleLocation = 12;
constexpr GLint kEmptySlotsLocation = 15;
constexpr GLint kSlotMatrixLocation = 16; // SLOT_COUNT (at most 16) locations
constexpr GLint kSlotLayerLocation = 32;  // likewise

} // namespace

CascadedGL::CascadedGL() : GlTechnique(Cascaded::declaration()) {}

int CascadedGL::slotCount() const {
    return mLights.empty() ? 1 : mLights.back().firstSlot + mLights.back().slots;
}

void CascadedGL::setScene(const Scene& scene) {
    mLights.clear();
    const size_t count = std::min<size_t>(scene.lights.size(), kMaxLights);
    const int cascades = int(properties().getInt(Cascaded::kCascades));
    Aabb casters = scene.computeBounds(true), all = scene.computeBounds(false);
    int slot = 0;
    for (size_t i = 0; i < count; ++i) {
        const Light& l = scene.lights[i];
        LightMaps m;
        m.castsShadows = l.castsShadows;
        if (m.castsShadows) PointLightRefusal::refuse(l, i, "cascaded");
        m.directional = l.type == LightType::Directional && m.castsShadows;
        m.firstSlot = slot;
        m.slots = m.directional ? cascades : 1;
        if (m.directional) {
            m.lightView = CascadeFit::lightView(l.direction);
            m.bounds = CascadeFit::sceneBounds(casters, all, m.lightView);
            m.cascades.resize(size_t(cascades));
        } else if (m.castsShadows) {
            m.spotViewProj = fitLightViewProjection(scene, l);
        }
        slot += m.slots;
        mLights.push_back(m);
    }
    mReceivers.clear();
    for (const Instance& inst : scene.instances)
        if (inst.receivesShadow && inst.mesh < scene.meshes.size())
            mReceivers.push_back(transformBounds(scene.meshes[inst.mesh].computeBounds(), inst.model));
    mSlotViewProj.assign(size_t(slotCount()), glm::mat4(1.0f));
    mSlotShadow.assign(size_t(slotCount()), glm::mat4(1.0f));
    mSlotLayer.assign(size_t(slotCount()), 0);
    mCulling.setScene(scene);
}

void CascadedGL::compile(const CompileContext& ctx) {
    const PropertySet& p = properties();
    mMaps.allocate(GL_TEXTURE_2D_ARRAY, int(p.getInt(P::kResolution)), slotCount(), false);
    Defines base = ctx.submitter.defines();
    mDepthProgram = &ctx.programs.get({"shadowmap/depth.vert", "shadowmap/depth.frag", ""}, base);
    Defines lit = ctx.defines(); // the depth pass has no shadow to apply
    lit["LIGHT_COUNT"] = std::to_string(std::max<size_t>(1, mLights.size()));
    lit["SLOT_COUNT"] = std::to_string(slotCount());
    lit["CASCADE_COUNT"] = std::to_string(p.getInt(Cascaded::kCascades));
    std::string first, slots;
    for (const LightMaps& m : mLights) {
        first += (first.empty() ? "" : ", ") + std::to_string(m.firstSlot);
        slots += (slots.empty() ? "" : ", ") + std::to_string(m.slots);
    }
    lit["FIRST_SLOTS"] = first.empty() ? "0" : first;
    lit["LIGHT_SLOTS"] = slots.empty() ? "0" : slots;
    if (p.getInt(Cascaded::kCascades) > 1 && p.getFloat(Cascaded::kBlend) > 0.0) lit["BLEND"] = "";
    lit["PCF_SIZE"] = std::to_string(p.getInt(P::kPcf));
    mLightingProgram = &ctx.programs.get({"common/scene.vert", "shadowmap/cascaded_lighting.frag", ""}, lit);
    setPermutationKey(mDepthProgram->key() + "|" + mLightingProgram->key());
}

void CascadedGL::fitCascades(const FrameContext& ctx) {
    const PropertySet& p = properties();
    const int n = int(p.getInt(Cascaded::kCascades));
    const glm::vec2 range =
        CascadeSplits::clipToReceivers(CascadeSplits::nearFar(ctx.proj), ctx.view, ctx.proj, mReceivers);
    mSplits = CascadeSplits::practical(range.x, range.y, n, float(p.getFloat(Cascaded::kLambda)));
    // Cascade c is looked up from mSplits[c] on, but blends in over the last `blend` of cascade c - 1:
    // its map must cover that band too.
    const float blend = float(p.getFloat(Cascaded::kBlend));
    mFitStart.assign(size_t(n), range.x);
    for (int c = 1; c < n; ++c)
        mFitStart[size_t(c)] = mSplits[size_t(c)] - blend * (mSplits[size_t(c)] - mSplits[size_t(c) - 1]);
    const bool stable = p.getBool(Cascaded::kStabilize);
    for (LightMaps& m : mLights) {
        if (!m.directional) {
            mSlotViewProj[size_t(m.firstSlot)] = m.spotViewProj;
            mSlotLayer[size_t(m.firstSlot)] = m.firstSlot;
            continue;
        }
        for (int c = 0; c < n; ++c) {
            Cascade& cascade = m.cascades[size_t(c)];
            cascade = CascadeFit::fit(m.lightView, ctx.view, ctx.proj, mFitStart[size_t(c)],
                                      mSplits[size_t(c) + 1], m.bounds, mMaps.size(), stable);
            mSlotViewProj[size_t(m.firstSlot + c)] = cascade.viewProj;
        }
        shareIdenticalFits(m);
    }
    for (size_t i = 0; i < mSlotViewProj.size(); ++i)
        mSlotShadow[i] = FlatLightFits::textureBias() * mSlotViewProj[i];
}

void CascadedGL::shareIdenticalFits(const LightMaps& m) {
    // A cascade whose fit equals the one before it (both clamped to the whole casters' bounds, as the
    // far cascades of an overview are) reads that map instead of drawing the same one again.
    for (int c = 0; c < m.slots; ++c) {
        const size_t slot = size_t(m.firstSlot + c);
        mSlotLayer[slot] = int(slot);
        if (c > 0 && std::memcmp(&mSlotViewProj[slot], &mSlotViewProj[slot - 1], sizeof(glm::mat4)) == 0)
            mSlotLayer[slot] = mSlotLayer[slot - 1];
    }
}

void CascadedGL::renderDepth(FrameContext& ctx) {
    const PropertySet& p = properties();
    DepthPassState state(mMaps.size(), float(p.getFloat(P::kBiasSlope)), float(p.getFloat(P::kBiasConstant)));
    // Casters nearer the light than a box's near side are not culled (SidesAndFar); clamping keeps any
    // that rounding puts in front of it in the map ("pancaking").
    glEnable(GL_DEPTH_CLAMP);
    mDepthProgram->use();
    mCulled = 0;
    mEmptySlots = 0;
    mMapsRendered = 0;
    for (const LightMaps& m : mLights)
        for (int c = 0; c < m.slots; ++c) {
            const size_t slot = size_t(m.firstSlot + c);
            if (!m.castsShadows) { // an unshadowed light's slot: never drawn, looked up as lit
                mEmptySlots |= 1u << slot;
                continue;
            }
            if (mSlotLayer[slot] != int(slot)) { // shares the map of the cascade before it
                if (mEmptySlots & (1u << (slot - 1))) mEmptySlots |= 1u << slot;
                continue;
            }
            // A spot map's frustum starts at the scene's nearest point: every plane culls.
            const CullPlanes planes = m.directional ? CullPlanes::SidesAndFar : CullPlanes::All;
            const size_t kept = mCulling.cull(mSlotViewProj[slot], DrawSet::Casters, planes, mKeep);
            mCulled += mCulling.count(DrawSet::Casters) - kept;
            if (kept == 0) { // nothing to shadow with: no clear, no draw, the lookup says lit
                mEmptySlots |= 1u << slot;
                continue;
            }
            mMaps.beginLayer(int(slot));
            glUniformMatrix4fv(kLightMatrixLocation, 1, GL_FALSE, glm::value_ptr(mSlotViewProj[slot]));
            ctx.submitter.draw(DrawSet::Casters, mKeep);
            ++mMapsRendered;
        }
    glDisable(GL_DEPTH_CLAMP);
}

void CascadedGL::renderLighting(FrameContext& ctx) {
    ctx.targets.bind();
    mLightingProgram->use();
    const int n = int(properties().getInt(Cascaded::kCascades));
    glm::vec4 splitFar(FLT_MAX), bandStart(FLT_MAX), bandScale(0.0f);
    // No splits when the frame skipped its depth pass (ShadowWork::noneNeeded): nothing is looked up.
    for (int c = 0; c + 1 < int(mSplits.size()) && c < n; ++c) {
        splitFar[c] = mSplits[size_t(c) + 1];
        if (c + 1 == n) break; // the last cascade blends into nothing
        const float band =
            float(properties().getFloat(Cascaded::kBlend)) * (mSplits[size_t(c) + 1] - mSplits[size_t(c)]);
        bandStart[c] = splitFar[c] - band;
        bandScale[c] = band > 0.0f ? 1.0f / band : 0.0f;
    }
    glUniform4fv(kSplitFarLocation, 1, glm::value_ptr(splitFar));
    glUniform4fv(kBandStartLocation, 1, glm::value_ptr(bandStart));
    glUniform4fv(kBandScaleLocation, 1, glm::value_ptr(bandScale));
    glUniform1ui(kEmptySlotsLocation, mEmptySlots);
    glUniformMatrix4fv(kSlotMatrixLocation, GLsizei(mSlotShadow.size()), GL_FALSE,
                       glm::value_ptr(mSlotShadow[0]));
    glUniform1iv(kSlotLayerLocation, GLsizei(mSlotLayer.size()), mSlotLayer.data());
    glBindTextureUnit(0, mMaps.texture());
    ctx.submitter.draw(DrawSet::All);
    glBindTextureUnit(0, 0);
}

void CascadedGL::execute(FrameContext& ctx) {
    const SubmitStats s = DepthLightingFrame::run(
        ctx,
        [&] {
            fitCascades(ctx);
            renderDepth(ctx);
        },
        [&] { renderLighting(ctx); });
    double cascades = 0.0;
    for (const LightMaps& m : mLights) cascades += m.directional ? m.slots : 0;
    // Texels of the maps drawn this frame: shared and empty cascades draw none.
    mCounters = {{"draw_calls", double(s.drawCalls)},
                 {"triangles", double(s.triangles)},
                 {"shadow_map_texels", double(mMaps.size()) * mMaps.size() * double(mMapsRendered)},
                 {"cascades", cascades},
                 {"casters_culled", double(mCulled)},
                 {"lights_unshadowed", double(ShadowWork::unshadowedLights(ctx.scene, mLights.size()))}};
}

} // namespace sb
