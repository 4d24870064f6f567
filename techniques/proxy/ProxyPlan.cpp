#include "techniques/proxy/ProxyPlan.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "scenes/ProxyCollection.h"
#include "shading/ShaderLimits.h"
#include "techniques/proxy/Proxy.h"

namespace sb {

namespace {
/// auto|on|off -> on, given what `auto` means for this scene.
bool resolve(const std::string& value, bool automatic) {
    return value == "auto" ? automatic : value == "on";
}
} // namespace

void ProxyPlan::setScene(const Scene& scene, const PropertySet& properties) {
    mLights = std::clamp<int>(int(scene.lights.size()), 1, kMaxLights);
    std::vector<uint32_t> owners;
    mProxies = ProxyCollection::collect(scene, properties.getEnum(Proxy::kProxies) == "fit", &owners);
    mRecords.clear();
    for (size_t i = 0; i < mProxies.size(); ++i) {
        const ShadowProxy& p = mProxies[i];
        GpuProxy g;
        g.toWorld = p.frame;
        g.toLocal = glm::inverse(p.frame);
        g.diffuse = glm::vec4(p.diffuse, float(int(p.shape)));
        g.reflective = glm::vec4(p.reflective, float(owners[i]));
        mRecords.push_back(g);
    }
    mUseGrid = properties.getBool(Proxy::kGrid);
    mCells = int(properties.getInt(Proxy::kCells));
    mCapacity = int(properties.getInt(Proxy::kCapacity));
    const std::string modulate = properties.getEnum(Proxy::kModulate);
    mModulate = modulate == "auto" ? !scene.lights.empty() : modulate != "off";
    mRays = mModulate && modulate != "on";
    mBleed = resolve(properties.getEnum(Proxy::kBleeding), hasEffect(scene.effects, Effect::ColourBleeding));
    mWarnedOverflow = false;
}

Defines ProxyPlan::defines(Defines d, const PropertySet& properties) const {
    d["LIGHT_COUNT"] = std::to_string(mLights);
    if (mUseGrid) d["PROXY_GRID"] = "";
    if (mModulate) d["PROXY_MODULATE"] = "";
    if (mRays) d["PROXY_RAYS"] = "";
    if (mBleed) d["PROXY_BLEED"] = "";
    if (properties.getEnum(Proxy::kExponentOn) == "factor") d["PROXY_EXPONENT_ON_FACTOR"] = "";
    return d;
}

size_t ProxyPlan::indexEntries(const PropertySet& properties) const {
    const size_t cells = size_t(properties.getInt(Proxy::kCells));
    return std::max<size_t>(1, cells * cells * size_t(properties.getInt(Proxy::kCapacity)));
}

void ProxyPlan::build(const glm::mat4& viewProj, const PropertySet& properties) {
    // Steps 2 and 3 of section 1.3 on the CPU, every frame (the camera may have moved).
    const float offset = float(properties.getFloat(Proxy::kOffset));
    if (mUseGrid)
        mGrid.build(mProxies, viewProj, offset, mCells, mCells, mCapacity);
    else // clipping only: one cell holding every proxy in view
        mGrid.build(mProxies, viewProj, offset, 1, 1, std::max<int>(1, int(mProxies.size())));
    mInView.clear();
    for (uint32_t i : mGrid.visible()) mInView.push_back(mRecords[i]);
    if (mGrid.overflow() > 0 && !mWarnedOverflow) {
        std::fprintf(stderr,
                     "proxy: %llu proxy entries did not fit their IndexMap cells (capacity %d, most wanted "
                     "more); their shadows are missing there: raise -t proxy:capacity=N (counter "
                     "grid_overflow)\n",
                     static_cast<unsigned long long>(mGrid.overflow()), mCapacity);
        mWarnedOverflow = true;
    }
}

ProxyPlan::Uniforms ProxyPlan::uniforms(const PropertySet& p, int width, int height) const {
    Uniforms u;
    u.shading = glm::vec4(float(p.getFloat(Proxy::kOffset)), float(p.getFloat(Proxy::kShadow)),
                          float(p.getFloat(Proxy::kFalloff)), float(p.getFloat(Proxy::kCutoff)));
    u.start = float(p.getFloat(Proxy::kStart));
    u.penumbra = std::tan(glm::radians(float(p.getFloat(Proxy::kPenumbra))));
    u.bleed = float(p.getFloat(Proxy::kBleed));
    u.cells = glm::ivec2(mCells, mCells);
    u.viewport = glm::vec2(float(width), float(height));
    u.capacity = mCapacity;
    u.count = int32_t(mInView.size());
    return u;
}

Counters ProxyPlan::counters(const SubmitStats& s) const {
    return {{"draw_calls", double(s.drawCalls)},        {"triangles", double(s.triangles)},
            {"proxies", double(mProxies.size())},       {"proxies_in_view", double(mInView.size())},
            {"grid_entries", double(mGrid.entries())},  {"grid_max_per_cell", double(mGrid.maxCount())},
            {"grid_overflow", double(mGrid.overflow())}};
}

} // namespace sb
