#include "techniques/shadowmap/ShadowMapTechnique.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "core/Injection.h"
#include "scenes/Math.h"
#include "techniques/shadowmap/DepthLightingFrame.h"
#include "techniques/shadowmap/DepthPassState.h"
#include "techniques/shadowmap/PoissonDisk.h"
#include "techniques/shadowmap/ShadowMapProperties.h"

namespace sb {

namespace {
using P = ShadowMapProperties;
constexpr const char* kHardwareCompare = "hardware_compare";
constexpr const char* kKernel = "kernel";
constexpr const char* kTaps = "taps";
constexpr const char* kRadius = "radius";
constexpr const char* kNormalOffset = "normal_offset";
constexpr const char* kCull = "cull";
constexpr const char* kReceiverPlane = "receiver_plane";
// shadowmap/lighting.frag: uTexelWorld[LIGHT_COUNT], uNormalOffset, uKernelTaps, uKernel[64].
constexpr GLint kTexelWorldLocation = 12;
constexpr GLint kNormalOffsetLocation = 16;
constexpr GLint kKernelTapsLocation = 17;
constexpr GLint kKernelLocation = 20; // uKernel[64]

/// The knobs, one maker call each (techniques/Property.h): what --list shows and -t name:k=v sets.
std::vector<PropertyDesc> declareProperties() {
    return {
        P::resolution("2048", "shadow map width and height (texels)"),
        P::biasConstant(),
        P::biasSlope(),
        P::pcf("PCF kernel width: pcf x pcf taps one texel apart"),
        flag(kHardwareCompare, "true",
             "depth-compare sampler with bilinear filtering (true) or nearest fetch + shader compare"),
        choice(kKernel, "grid", {"grid", "poisson", "rotated_grid"},
               "PCF kernel: grid (pcf x pcf), poisson (taps of a fixed Poisson disk), rotated_grid (a grid "
               "rotated per pixel by interleaved gradient noise)"),
        integer(kTaps, "16", 4, 64,
                "taps of the poisson kernel; rotated_grid uses the nearest square n x n (n >= 2)"),
        real(kRadius, "1.5", 0, 64, "radius of the poisson and rotated_grid kernels (map texels)"),
        real(kNormalOffset, "0", 0, 64,
             "normal-offset bias: lookup moved along the normal by this many world texels x (1 - n.l)"),
        flag(kReceiverPlane, "false", "receiver-plane depth bias: each tap compared with the receiver plane"),
        flag(kCull, "true",
             "leave out of each light's map the casters whose shadow cannot reach the view (grown by the "
             "filter's footprint)"),
    };
}

/// Side of the rotated grid for `taps`: the nearest square, at least 2 x 2.
int rotatedGridSide(int taps) {
    return std::max(2, int(std::lround(std::sqrt(double(taps)))));
}

/// The kernel's tap offsets in texels, `radius` applied: the Poisson disk scaled to the radius, or the
/// unrotated n x n grid of cell centres covering the square [-radius, radius]^2.
std::vector<glm::vec2> kernelTaps(const std::string& kernel, int taps, float radius) {
    std::vector<glm::vec2> out;
    if (kernel == "poisson") {
        for (const glm::vec2& p : PoissonDisk::generate(taps)) out.push_back(p * radius);
        return out;
    }
    const int n = rotatedGridSide(taps);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            out.push_back((glm::vec2(float(x), float(y)) + 0.5f - 0.5f * float(n)) *
                          (2.0f * radius / float(n)));
    return out;
}

} // namespace

TechniqueInfo ShadowMapTechnique::describe() {
    return {.name = "shadowmap",
            .description = "two-pass shadow mapping: depth from each light, compare in the lighting pass",
            .effects = Effect::HardShadows | Effect::SelfShadowing | Effect::NonPlanarReceivers |
                       Effect::MultipleLights,
            .capabilities = {{"GL 4.5", 4, 5, ""}},
            .passes = {"depth", "lighting"},
            .properties = declareProperties(),
            // What `bench accuracy --sweep` walks, one knob at a time around the defaults.
            .quality = {
                {P::kResolution, {"256", "512", "1024", "2048", "4096"}},
                P::pcfSweep(),
                P::biasConstantSweep(),
                P::biasSlopeSweep(),
                {kKernel, {"grid", "poisson", "rotated_grid"}},
                {kTaps, {"8", "16", "32"}},
                {kRadius, {"1", "1.5", "3"}},
                {kNormalOffset, {"0", "1", "2", "4"}},
                {kReceiverPlane, {"false", "true"}},
            }};
}

ShadowMapTechnique::ShadowMapTechnique() : Technique(describe()) {}

void ShadowMapTechnique::setScene(const Scene& scene) {
    mLights.setScene(scene, "shadowmap", FlatLightFits::kOmniAdvice);
    mCulling.setScene(scene);
}

void ShadowMapTechnique::compile(const CompileContext& ctx) {
    const PropertySet& p = properties();
    int layers = std::max<int>(1, int(mLights.size()));
    // The perf gate's proof may double the map per side (core/Injection.h); the row's properties
    // still say the configured resolution, its `injected` column says what ran.
    const int scale = injected(Injection::DoubleShadowResolution) ? 2 : 1;
    mMaps.allocate(GL_TEXTURE_2D_ARRAY, scale * int(p.getInt(P::kResolution)), layers, false);
    const GLuint depthArray = mMaps.texture();
    bool hw = p.getBool(kHardwareCompare);
    // Hardware compare: LINEAR filters the four comparison results (bilinear PCF); without it the shader
    // compares NEAREST depth values itself.
    glTextureParameteri(depthArray, GL_TEXTURE_COMPARE_MODE, hw ? GL_COMPARE_REF_TO_TEXTURE : GL_NONE);
    glTextureParameteri(depthArray, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glTextureParameteri(depthArray, GL_TEXTURE_MIN_FILTER, hw ? GL_LINEAR : GL_NEAREST);
    glTextureParameteri(depthArray, GL_TEXTURE_MAG_FILTER, hw ? GL_LINEAR : GL_NEAREST);

    mDrawAllIntoMap = injected(Injection::NoCasterCulling);
    Defines base = ctx.submitter.defines();
    mDepthProgram = &ctx.programs.get({"shadowmap/depth.vert", "shadowmap/depth.frag", ""}, base);
    Defines lit = ctx.defines(); // the depth pass has no shadow to apply
    lit["SHADOW_MAP"] = "";
    lit["LIGHT_COUNT"] = std::to_string(layers);
    if (hw) lit["HW_COMPARE"] = "";
    // Defaults add no define: the default program is the one before these knobs existed. The other
    // kernels take their taps as uniforms and ignore pcf, so neither `taps` nor `pcf` multiplies their
    // programs.
    const std::string kernel = p.getEnum(kKernel);
    mKernel.clear();
    if (kernel == "grid") {
        lit["PCF_SIZE"] = std::to_string(p.getInt(P::kPcf));
    } else {
        mKernel = kernelOffsets(p);
        lit[kernel == "poisson" ? "KERNEL_POISSON" : "KERNEL_ROTATED_GRID"] = "";
    }
    mNormalOffset = float(p.getFloat(kNormalOffset));
    if (mNormalOffset > 0.0f) lit["NORMAL_OFFSET"] = "";
    if (p.getBool(kReceiverPlane)) lit["RECEIVER_PLANE"] = "";
    mCull = p.getBool(kCull);
    fitTexels(ctx.scene);
    mLightingProgram = &ctx.programs.get({"common/scene.vert", "shadowmap/lighting.frag", ""}, lit);
    setPermutationKey(mDepthProgram->key() + "|" + mLightingProgram->key());
}

std::vector<glm::vec2> ShadowMapTechnique::kernelOffsets(const PropertySet& p) {
    const std::string& kernel = p.getEnum(kKernel);
    if (kernel == "grid") return {};
    return kernelTaps(kernel, int(p.getInt(kTaps)), float(p.getFloat(kRadius)));
}

void ShadowMapTechnique::sceneChanged(const Scene& scene, uint32_t) {
    setScene(scene);
    fitTexels(scene);
}

void ShadowMapTechnique::fitTexels(const Scene& scene) {
    const PropertySet& p = properties();
    const double kernel = mKernel.empty() ? double(p.getInt(P::kPcf)) : p.getFloat(kRadius);
    fitTexels(scene, mLights, mMaps.size(), kernel, mNormalOffset, mTexelWorld, mView);
}

void ShadowMapTechnique::fitTexels(const Scene& scene, const FlatLightFits& lights, int mapSize,
                                   double kernelTexels, float normalOffset, std::vector<float>& texelWorld,
                                   ViewCull& view) {
    texelWorld.clear();
    for (const glm::mat4& vp : lights.viewProj())
        texelWorld.push_back(FlatLightFits::texelWorldSize(vp, mapSize));
    // What the lighting pass reads around a receiver's texel, in texels: the kernel's half-width (the
    // grid's pcf x pcf, the other kernels' radius), the normal offset, and two for the bilinear
    // compare's footprint and rounding. In world units at the farthest receiver (w = 1 for an
    // orthographic map; a spot's texels grow with the distance).
    const float texels = float(kernelTexels) + normalOffset + 2.0f;
    view.lights = &scene.lights;
    view.reach.receivers = Aabb{};
    for (const Instance& inst : scene.instances)
        if (inst.receivesShadow && inst.mesh < scene.meshes.size())
            view.reach.receivers.extend(transformBounds(scene.meshes[inst.mesh].computeBounds(), inst.model));
    view.margins.clear();
    for (size_t i = 0; i < lights.viewProj().size(); ++i)
        view.margins.push_back(texels * texelWorld[i] *
                               FlatLightFits::farthestW(lights.viewProj()[i], view.reach.receivers));
}

void ShadowMapTechnique::renderDepth(FrameContext& ctx) {
    const PropertySet& p = properties();
    DepthPassState state(mMaps.size(), float(p.getFloat(P::kBiasSlope)), float(p.getFloat(P::kBiasConstant)));
    mDepthProgram->use();
    // Only casters inside the light's frustum reach the map; the gate's proof can lose that culling
    // (core/Injection.h).
    mView.reach.camera = ctx.proj * ctx.view;
    mCulled = mLights.renderDepth(ctx.submitter, mCulling, mMaps, mKeep, mDrawAllIntoMap,
                                  mCull && !mDrawAllIntoMap ? &mView : nullptr);
}

void ShadowMapTechnique::renderLighting(FrameContext& ctx) {
    ctx.targets.bind();
    mLightingProgram->use();
    mLights.setShadowMatrices();
    if (mNormalOffset > 0.0f) {
        glUniform1fv(kTexelWorldLocation, GLsizei(mTexelWorld.size()), mTexelWorld.data());
        glUniform1f(kNormalOffsetLocation, mNormalOffset);
    }
    if (!mKernel.empty()) {
        glUniform1i(kKernelTapsLocation, GLint(mKernel.size()));
        glUniform2fv(kKernelLocation, GLsizei(mKernel.size()), glm::value_ptr(mKernel[0]));
    }
    glBindTextureUnit(0, mMaps.texture());
    ctx.submitter.draw(DrawSet::All);
    glBindTextureUnit(0, 0);
}

void ShadowMapTechnique::execute(FrameContext& ctx) {
    const SubmitStats s = DepthLightingFrame::run(
        ctx, [&] { renderDepth(ctx); }, [&] { renderLighting(ctx); });
    mCounters = {{"draw_calls", double(s.drawCalls)},
                 {"triangles", double(s.triangles)},
                 {"shadow_map_texels", double(mMaps.size()) * mMaps.size() * double(mLights.shadowed())},
                 {"lights_unshadowed", double(mLights.size() - mLights.shadowed())},
                 {"casters_culled", double(mCulled)}};
}

} // namespace sb
