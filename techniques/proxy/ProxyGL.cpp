#include "techniques/proxy/ProxyTechnique.h"

#include <algorithm>
#include <cstdio>

#include "core/Error.h"

namespace sb {

namespace {
constexpr const char* kOffset = "offset";
constexpr const char* kShadow = "shadow";
constexpr const char* kFalloff = "falloff";
constexpr const char* kExponentOn = "exponent_on";
constexpr const char* kStart = "start";
constexpr const char* kCutoff = "cutoff";
constexpr const char* kBleed = "bleed";
constexpr const char* kBleeding = "bleeding";
constexpr const char* kModulate = "modulate";
constexpr const char* kGrid = "grid";
constexpr const char* kCells = "cells";
constexpr const char* kCapacity = "capacity";
constexpr const char* kProxies = "proxies";
// shaders/proxy/lit.frag
constexpr GLuint kProxyBinding = 2, kIndexBinding = 3;
constexpr GLint kShadingLocation = 16, kBleedLocation = 17, kStartLocation = 18, kCellsLocation = 20,
                kViewportLocation = 21, kCapacityLocation = 22, kCountLocation = 23;

/// auto|on|off -> on, given what `auto` means for this scene.
bool resolve(const std::string& value, bool automatic) {
    return value == "auto" ? automatic : value == "on";
}

/// The knobs, one maker call each (techniques/Property.h): what --list shows and -t name:k=v sets.
std::vector<PropertyDesc> declareProperties() {
    return {
        real(kOffset, "1", 0, 1e6,
             "ProxyOffset: how far (world units) beyond the proxy's surface its influence reaches"),
        real(kShadow, "1", 0, 1, "shadow factor: the shadow at the surface"),
        real(kFalloff, "1", 0.01, 64, "falloff exponent of the attenuation"),
        choice(kExponentOn, "attenuation", {"attenuation", "factor"},
               "attenuation: pow(1 - d/offset, falloff) (section 1.2's text); factor: Listing 1.3 as "
               "printed, (1 - d/offset) * pow(shadow, falloff)"),
        real(kStart, "0", 0, 1e6,
             "distance from the surface where the falloff starts (section 1.2's offset between surface and "
             "falloff)"),
        real(kCutoff, "0", -1, 1,
             "Listing 1.4's lower clamp of dot(light, normal): above 0 the shadow wraps round the lit side"),
        real(kBleed, "0.5", 0, 1, "amount of colour bleeding at the surface"),
        choice(kBleeding, "auto", {"auto", "on", "off"},
               "colour bleeding compiled in: auto = when the scene asks for colour_bleeding"),
        choice(kModulate, "auto", {"auto", "on", "off"},
               "egg-shaped volumes towards/away from each light (Listing 1.4): auto = when the scene has "
               "lights"),
        flag(kGrid, "true", "screen-space IndexMap (true) or every proxy in view tested by every fragment"),
        integer(kCells, "64", 1, 1024, "IndexMap grid cells along x and along y"),
        integer(kCapacity, "16", 1, 4096,
                "proxy indices per cell; more are counted as grid_overflow, never silently dropped"),
        choice(kProxies, "scene", {"scene", "fit"},
               "scene: the meshes' declared proxies, fitted where none are declared; fit: fit every caster "
               "(the tightest of sphere, box and cylinder)"),
    };
}
} // namespace

ProxyTechnique::ProxyTechnique()
    : Technique(
          {.name = "proxy",
           .description =
               "ShadowProxies: analytic sphere/box/cylinder volumes, screen-space index grid, soft "
               "shadows and colour bleeding (van der Spek, OpenGL Insights)",
           // Soft halos around proxies: not exact hard shadows, no self-shadowing (the proxy of the
           // fragment's own object is skipped), any receiver shape.
           .effects = Effect::SoftShadows | Effect::ColourBleeding | Effect::NonPlanarReceivers |
                      Effect::MultipleLights,
           .capabilities = {{"GL 4.5", 4, 5, ""}},
           .passes = {"index_map", "lighting"},
           .properties = declareProperties(),
           .quality = {{kOffset, {"0.25", "0.5", "1", "2", "4"}}, {kFalloff, {"0.5", "1", "2", "4"}}}}) {}

ProxyTechnique::~ProxyTechnique() {
    release();
}

void ProxyTechnique::release() {
    if (mProxyBuffer) glDeleteBuffers(1, &mProxyBuffer);
    if (mIndexBuffer) glDeleteBuffers(1, &mIndexBuffer);
    mProxyBuffer = mIndexBuffer = 0;
    mProxyCapacity = mIndexCapacity = 0;
}

void ProxyTechnique::setScene(const Scene& scene) {
    mLights = std::clamp<int>(int(scene.lights.size()), 1, kMaxLights);
    std::vector<uint32_t> owners;
    mProxies = ProxyCollection::collect(scene, properties().getEnum(kProxies) == "fit", &owners);
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
    mUseGrid = properties().getBool(kGrid);
    mCells = int(properties().getInt(kCells));
    mCapacity = int(properties().getInt(kCapacity));
    mModulate = resolve(properties().getEnum(kModulate), !scene.lights.empty());
    mBleed = resolve(properties().getEnum(kBleeding), hasEffect(scene.effects, Effect::ColourBleeding));
    mWarnedOverflow = false;
}

void ProxyTechnique::compile(const CompileContext& ctx) {
    Defines d = ctx.defines();
    d["LIGHT_COUNT"] = std::to_string(mLights);
    if (mUseGrid) d["PROXY_GRID"] = "";
    if (mModulate) d["PROXY_MODULATE"] = "";
    if (mBleed) d["PROXY_BLEED"] = "";
    if (properties().getEnum(kExponentOn) == "factor") d["PROXY_EXPONENT_ON_FACTOR"] = "";
    mProgram = &ctx.programs.get({"common/scene.vert", "proxy/lit.frag", ""}, d);
    setPermutationKey(mProgram->key());
    if (!mProxyBuffer) glCreateBuffers(1, &mProxyBuffer);
    if (!mIndexBuffer) glCreateBuffers(1, &mIndexBuffer);
}

void ProxyTechnique::uploadFrame(FrameContext& ctx) {
    // Steps 2 and 3 of section 1.3 on the CPU, every frame (the camera may have moved).
    const glm::mat4 viewProj = ctx.proj * ctx.view;
    const float offset = float(properties().getFloat(kOffset));
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

void ProxyTechnique::execute(FrameContext& ctx) {
    ctx.submitter.resetStats();
    ctx.passes.begin("index_map");
    uploadFrame(ctx);
    ctx.passes.begin("lighting");
    ctx.targets.bind();
    mProgram->use();
    const PropertySet& p = properties();
    glUniform4f(kShadingLocation, float(p.getFloat(kOffset)), float(p.getFloat(kShadow)),
                float(p.getFloat(kFalloff)), float(p.getFloat(kCutoff)));
    glUniform1f(kStartLocation, float(p.getFloat(kStart)));
    if (mBleed) glUniform1f(kBleedLocation, float(p.getFloat(kBleed)));
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
