#include "techniques/proxy/ProxyGL.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/Error.h"

namespace sb {

namespace {
// shaders/proxy/lit.frag
constexpr GLuint kProxyBinding = 2, kIndexBinding = 3;
constexpr GLint kShadingLocation = 16, kBleedLocation = 17, kStartLocation = 18, kPenumbraLocation = 19,
                kCellsLocation = 20, kViewportLocation = 21, kCapacityLocation = 22, kCountLocation = 23;

/// auto|on|off -> on, given what `auto` means for this scene.
bool resolve(const std::string& value, bool automatic) {
    return value == "auto" ? automatic : value == "on";
}

} // namespace

ProxyGL::ProxyGL() : GlTechnique(Proxy::declaration()) {}

ProxyGL::~ProxyGL() {
    release();
}

void ProxyGL::release() {
    if (mProxyBuffer) glDeleteBuffers(1, &mProxyBuffer);
    if (mIndexBuffer) glDeleteBuffers(1, &mIndexBuffer);
    mProxyBuffer = mIndexBuffer = 0;
    mProxyCapacity = mIndexCapacity = 0;
}

void ProxyGL::setScene(const Scene& scene) {
    mLights = std::clamp<int>(int(scene.lights.size()), 1, kMaxLights);
    std::vector<uint32_t> owners;
    mProxies = ProxyCollection::collect(scene, properties().getEnum(Proxy::kProxies) == "fit", &owners);
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
    mUseGrid = properties().getBool(Proxy::kGrid);
    mCells = int(properties().getInt(Proxy::kCells));
    mCapacity = int(properties().getInt(Proxy::kCapacity));
    const std::string modulate = properties().getEnum(Proxy::kModulate);
    mModulate = modulate == "auto" ? !scene.lights.empty() : modulate != "off";
    mRays = mModulate && modulate != "on";
    mBleed =
        resolve(properties().getEnum(Proxy::kBleeding), hasEffect(scene.effects, Effect::ColourBleeding));
    mWarnedOverflow = false;
}

void ProxyGL::compile(const CompileContext& ctx) {
    Defines d = ctx.defines();
    d["LIGHT_COUNT"] = std::to_string(mLights);
    if (mUseGrid) d["PROXY_GRID"] = "";
    if (mModulate) d["PROXY_MODULATE"] = "";
    if (mRays) d["PROXY_RAYS"] = "";
    if (mBleed) d["PROXY_BLEED"] = "";
    if (properties().getEnum(Proxy::kExponentOn) == "factor") d["PROXY_EXPONENT_ON_FACTOR"] = "";
    mProgram = &ctx.programs.get({"common/scene.vert", "proxy/lit.frag", ""}, d);
    setPermutationKey(mProgram->key());
    if (!mProxyBuffer) glCreateBuffers(1, &mProxyBuffer);
    if (!mIndexBuffer) glCreateBuffers(1, &mIndexBuffer);
}

void ProxyGL::uploadFrame(FrameContext& ctx) {
    // Steps 2 and 3 of section 1.3 on the CPU, every frame (the camera may have moved).
    const glm::mat4 viewProj = ctx.proj * ctx.view;
    const float offset = float(properties().getFloat(Proxy::kOffset));
    if (mUseGrid)
        mGrid.build(mProxies, viewProj, offset, mCells, mCells, mCapacity);
    else // clipping only: one cell holding every proxy in view
        mGrid.build(mProxies, viewProj, offset, 1, 1, std::max<int>(1, int(mProxies.size())));
    mInView.clear();
    for (uint32_t i : mGrid.visible()) mInView.push_back(mRecords[i]);
    // Buffers grow (never shrink) to the largest frame; then only sub-data updates.
    const size_t proxies = std::max<size_t>(1, mInView.size());
    if (proxies > mProxyCapacity) {
        glNamedBufferData(mProxyBuffer, GLsizeiptr(proxies * sizeof(GpuProxy)), nullptr, GL_DYNAMIC_DRAW);
        mProxyCapacity = proxies;
    }
    if (!mInView.empty())
        glNamedBufferSubData(mProxyBuffer, 0, GLsizeiptr(mInView.size() * sizeof(GpuProxy)), mInView.data());
    if (mUseGrid) {
        const std::vector<uint32_t>& texels = mGrid.texels();
        if (texels.size() > mIndexCapacity) {
            glNamedBufferData(mIndexBuffer, GLsizeiptr(texels.size() * sizeof(uint32_t)), nullptr,
                              GL_DYNAMIC_DRAW);
            mIndexCapacity = texels.size();
        }
        glNamedBufferSubData(mIndexBuffer, 0, GLsizeiptr(texels.size() * sizeof(uint32_t)), texels.data());
    }
    if (mGrid.overflow() > 0 && !mWarnedOverflow) {
        std::fprintf(stderr,
                     "proxy: %llu proxy entries did not fit their IndexMap cells (capacity %d, most wanted "
                     "more); their shadows are missing there: raise -t proxy:capacity=N (counter "
                     "grid_overflow)\n",
                     static_cast<unsigned long long>(mGrid.overflow()), mCapacity);
        mWarnedOverflow = true;
    }
}

void ProxyGL::execute(FrameContext& ctx) {
    ctx.submitter.resetStats();
    ctx.passes.begin("index_map");
    uploadFrame(ctx);
    ctx.passes.begin("lighting");
    ctx.targets.bind();
    mProgram->use();
    const PropertySet& p = properties();
    glUniform4f(kShadingLocation, float(p.getFloat(Proxy::kOffset)), float(p.getFloat(Proxy::kShadow)),
                float(p.getFloat(Proxy::kFalloff)), float(p.getFloat(Proxy::kCutoff)));
    glUniform1f(kStartLocation, float(p.getFloat(Proxy::kStart)));
    if (mRays) glUniform1f(kPenumbraLocation, std::tan(glm::radians(float(p.getFloat(Proxy::kPenumbra)))));
    if (mBleed) glUniform1f(kBleedLocation, float(p.getFloat(Proxy::kBleed)));
    if (mUseGrid) {
        glUniform2i(kCellsLocation, mCells, mCells);
        glUniform2f(kViewportLocation, float(ctx.targets.width()), float(ctx.targets.height()));
        glUniform1i(kCapacityLocation, mCapacity);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kIndexBinding, mIndexBuffer);
    } else {
        glUniform1i(kCountLocation, GLint(mInView.size()));
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kProxyBinding, mProxyBuffer);
    ctx.submitter.draw(DrawSet::All);
    const SubmitStats& s = ctx.submitter.stats();
    mCounters = {{"draw_calls", double(s.drawCalls)},        {"triangles", double(s.triangles)},
                 {"proxies", double(mProxies.size())},       {"proxies_in_view", double(mInView.size())},
                 {"grid_entries", double(mGrid.entries())},  {"grid_max_per_cell", double(mGrid.maxCount())},
                 {"grid_overflow", double(mGrid.overflow())}};
}

} // namespace sb
