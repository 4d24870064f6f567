#include "techniques/shadowmap/CascadedMaps.h"

#include "techniques/ContactShadows.h"

#include <algorithm>
#include <cfloat>
#include <cstring>

#include "scenes/LightFit.h"
#include "scenes/Math.h"
#include "scenes/ShadowWork.h"
#include "shading/ShaderLimits.h"
#include "techniques/DepthLightingFrame.h"
#include "techniques/FlatLightFits.h"
#include "techniques/PointLightRefusal.h"
#include "techniques/ShadowMapProperties.h"
#include "techniques/shadowmap/CascadeSplits.h"
#include "techniques/shadowmap/Cascaded.h"

namespace sb {

namespace {
using P = ShadowMapProperties;
} // namespace

int CascadedMaps::slotCount() const {
    return mLights.empty() ? 1 : mLights.back().firstSlot + mLights.back().slots;
}

void CascadedMaps::setScene(const Scene& scene, int cascades) {
    mLights.clear();
    const size_t count = std::min<size_t>(scene.lights.size(), kMaxLights);
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
            mReceivers.push_back(transformBounds(scene.meshBoundsOf(inst.mesh), inst.model));
    mSlotViewProj.assign(size_t(slotCount()), glm::mat4(1.0f));
    mSlotShadow.assign(size_t(slotCount()), glm::mat4(1.0f));
    mSlotLayer.assign(size_t(slotCount()), 0);
    mCulling.setScene(scene);
}

void CascadedMaps::fit(const glm::mat4& view, const glm::mat4& proj, const PropertySet& p, int resolution,
                       glm::vec2 samples) {
    const int n = int(p.getInt(Cascaded::kCascades));
    mView = view;
    mResolution = resolution;
    mSamples = samples;
    if (Cascaded::sampleDistribution(p)) {
        mSplits = CascadeSplits::sampleDistribution(samples, CascadeSplits::nearFar(proj), n);
    } else {
        const glm::vec2 clipped =
            CascadeSplits::clipToReceivers(CascadeSplits::nearFar(proj), view, proj, mReceivers);
        mSplits = CascadeSplits::practical(clipped.x, clipped.y, n, float(p.getFloat(Cascaded::kLambda)));
    }
    const float nearest = mSplits.front();
    // Cascade c is looked up from mSplits[c] on, but blends in over the last `blend` of cascade c - 1:
    // its map must cover that band too.
    const float blend = float(p.getFloat(Cascaded::kBlend));
    mFitStart.assign(size_t(n), nearest);
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
            cascade = CascadeFit::fit(m.lightView, view, proj, mFitStart[size_t(c)], mSplits[size_t(c) + 1],
                                      m.bounds, resolution, stable);
            mSlotViewProj[size_t(m.firstSlot + c)] = cascade.viewProj;
        }
        shareIdenticalFits(m);
    }
    for (size_t i = 0; i < mSlotViewProj.size(); ++i)
        mSlotShadow[i] = FlatLightFits::textureBias() * mSlotViewProj[i];
}

std::optional<MapPoint> CascadedMaps::texel(size_t light, const ShadedPoint& at, const glm::dvec3& q) const {
    if (light >= mLights.size() || !mLights[light].castsShadows || mSplits.size() < 2) return std::nullopt;
    const LightMaps& m = mLights[light];
    int c = 0;
    if (m.directional) { // as visibility() in cascaded_lighting.frag: splitFar[k] is mSplits[k + 1]
        const float viewDepth = float(-(glm::dmat4(mView) * glm::dvec4(at.position, 1.0)).z);
        for (int k = 0; k + 1 < m.slots; ++k) c += viewDepth > mSplits[size_t(k) + 1] ? 1 : 0;
    }
    const size_t slot = size_t(m.firstSlot + c);
    if ((mEmptySlots & (1u << slot)) != 0 || !looksUp(mSlotShadow[slot], at.position)) return std::nullopt;
    return MapPoint{c, mResolution, projectedTexel(mSlotShadow[slot], mResolution, q)};
}

void CascadedMaps::shareIdenticalFits(const LightMaps& m) {
    // A cascade whose fit equals the one before it (both clamped to the whole casters' bounds, as the
    // far cascades of an overview are) reads that map instead of drawing the same one again.
    for (int c = 0; c < m.slots; ++c) {
        const size_t slot = size_t(m.firstSlot + c);
        mSlotLayer[slot] = int(slot);
        if (c > 0 && std::memcmp(&mSlotViewProj[slot], &mSlotViewProj[slot - 1], sizeof(glm::mat4)) == 0)
            mSlotLayer[slot] = mSlotLayer[slot - 1];
    }
}

int CascadedMaps::planDepth(std::vector<uint8_t>& keep, const std::function<void(size_t slot)>& draw) {
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
            const size_t kept = mCulling.cull(mSlotViewProj[slot], DrawSet::Casters, planes, keep);
            mCulled += mCulling.count(DrawSet::Casters) - kept;
            if (kept == 0) { // nothing to shadow with: no clear, no draw, the lookup says lit
                mEmptySlots |= 1u << slot;
                continue;
            }
            draw(slot);
            ++mMapsRendered;
        }
    return mMapsRendered;
}

CascadedMaps::SplitValues CascadedMaps::splitValues(const PropertySet& p) const {
    const int n = int(p.getInt(Cascaded::kCascades));
    SplitValues v{glm::vec4(FLT_MAX), glm::vec4(FLT_MAX), glm::vec4(0.0f)};
    // No splits when the frame skipped its depth pass (ShadowWork::noneNeeded): nothing is looked up.
    for (int c = 0; c + 1 < int(mSplits.size()) && c < n; ++c) {
        v.splitFar[c] = mSplits[size_t(c) + 1];
        if (c + 1 == n) break; // the last cascade blends into nothing
        const float band =
            float(p.getFloat(Cascaded::kBlend)) * (mSplits[size_t(c) + 1] - mSplits[size_t(c)]);
        v.bandStart[c] = v.splitFar[c] - band;
        v.bandScale[c] = band > 0.0f ? 1.0f / band : 0.0f;
    }
    return v;
}

Defines CascadedMaps::lightingDefines(Defines lit, const PropertySet& p) const {
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
    ContactShadows::addDefines(p, lit);
    return lit;
}

Counters CascadedMaps::counters(const SubmitStats& s, int resolution, const Scene& scene,
                                const PropertySet& p) const {
    double cascades = 0.0;
    for (const LightMaps& m : mLights) cascades += m.directional ? m.slots : 0;
    // Texels of the maps drawn this frame: shared and empty cascades draw none.
    const double res = double(resolution);
    std::vector<std::pair<std::string, double>> extra = {
        {"cascades", cascades},
        {"casters_culled", double(mCulled)},
        {"lights_unshadowed", double(ShadowWork::unshadowedLights(scene, mLights.size()))}};
    if (Cascaded::sampleDistribution(p)) {
        const bool covered = mSamples.x <= mSamples.y;
        extra.emplace_back("depth_min", covered ? double(mSamples.x) : 0.0);
        extra.emplace_back("depth_max", covered ? double(mSamples.y) : 0.0);
    }
    return DepthLightingFrame::counters(s, res * res * double(mMapsRendered), std::move(extra));
}

} // namespace sb
