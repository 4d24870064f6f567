#include "techniques/shadowmap/ParaboloidVulkan.h"

#include <algorithm>
#include <cstring>

#include "core/Error.h"
#include "techniques/ContactShadows.h"
#include "techniques/DepthLightingFrame.h"
#include "techniques/ShadowMapProperties.h"
#include "techniques/shadowmap/Paraboloid.h"
#include "techniques/vulkan/ScenePass.h"

namespace sb {

namespace {
using P = ShadowMapProperties;

/// std140 offsets of omni_lighting.glsl's block for `lights` lights: mat4 uShadowMatrix[], then
/// ivec2 uMap[] and vec2 uDepthRange[], 16 bytes per element.
struct BlockLayout {
    explicit BlockLayout(uint32_t lights) : maps(64 * lights), ranges(80 * lights), size(96 * lights) {}
    uint32_t maps, ranges, size;
};

/// paraboloid_depth.vert's and paraboloid_split.geom's ParaboloidPass (std140).
struct ParaboloidPass {
    glm::vec4 light; ///< xyz position, w half
    glm::vec2 nearFar;
    float maxAngle;
    float beyondRim;
};
static_assert(sizeof(ParaboloidPass) == 32);

/// A slot's descriptor range: depth.vert's LightPass (a mat4), which holds a ParaboloidPass too.
constexpr uint32_t kSlotBytes = 64;

} // namespace

ParaboloidVulkan::ParaboloidVulkan() : VulkanTechnique(Paraboloid::declaration()) {}

ParaboloidVulkan::~ParaboloidVulkan() {
    release();
}

void ParaboloidVulkan::release() {
    if (!mDevice) return;
    vkDestroyPipelineLayout(mDevice, mDepthLayout, nullptr);
    vkDestroyPipelineLayout(mDevice, mLightingLayout, nullptr);
    mSets = DescriptorSets();
    mDepthLayout = mLightingLayout = VK_NULL_HANDLE;
    mFlatDepth = mParaboloidDepth = mSplitDepth = VK_NULL_HANDLE; // owned by the pipeline cache
    mMaps = VulkanDepthMapSet();
    mLightingBlock = VulkanBuffer();
}

void ParaboloidVulkan::propertiesApplied() {
    mutableInfo().passes = ContactShadows::passes(properties(), Paraboloid::declaration().passes);
}

void ParaboloidVulkan::setScene(const Scene& scene) {
    mLights.setScene(scene, OmniShape::Paraboloid, int(properties().getInt(P::kResolution)));
    mCulling.setScene(scene);
    mOmniCulling.setScene(scene);
    mSplitting.setScene(scene);
}

void ParaboloidVulkan::sceneChanged(const Scene& scene, uint32_t) {
    setScene(scene);
    // The harness waits for each frame's fence before the next is recorded: no slot is in flight.
    if (mLightingBlock.map()) writeBlocks();
}

void ParaboloidVulkan::checkFeatures(const VulkanContext& context) const {
    VkPhysicalDeviceFeatures features{};
    vkGetPhysicalDeviceFeatures(context.physicalDevice(), &features); // VulkanContext enables these
    auto refuse = [&](const std::string& feature, const std::string& why) {
        throw Error("paraboloid: the Vulkan device '" + context.info().name + "' has no " + feature + " (" +
                        why + "); run it with --api gl",
                    ExitCode::Unsupported);
    };
    if (!features.shaderClipDistance) refuse("shaderClipDistance", "the cut at each half's plane");
    if (mSplit && !features.geometryShader)
        refuse("geometryShader", "split=true's splitting stage; split=false projects per vertex only");
}

void ParaboloidVulkan::createDescriptors(VulkanContext& context) {
    // As DepthLayers on GL: hardware compare (LEQUAL) with LINEAR, the four comparison results filtered.
    const VkSampler sampler = mMaps.addSampler(true);
    mMaps.createSlots(context, kSlotBytes, uint32_t(std::max(1, mFlatCount + 2 * mOmniCount)));
    // Set 1 of the depth passes: a dynamic slot per pass (LightPass or ParaboloidPass). Set 1 of the
    // lighting pass: the lights' block and the map array.
    using D = DescriptorSets;
    mSets = DescriptorSets(
        mDevice,
        {{D::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC,
                     VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_GEOMETRY_BIT)},
         {D::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                     VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT),
          D::binding(1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT)}},
        "paraboloid");
    const BlockLayout block{uint32_t(mLights.shaderLightCount())};
    mLightingBlock = VulkanBuffer(context, block.size, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    std::memset(mLightingBlock.map(), 0, block.size);

    mSets.writeBuffer(kDepthSet, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, mMaps.slots().buffer(),
                      mMaps.slots().bytes());
    mSets.writeBuffer(kLightingSet, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, mLightingBlock.buffer(),
                      block.size);
    mSets.writeImage(kLightingSet, 1, sampler, mMaps.view(), VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
}

void ParaboloidVulkan::writeBlocks() {
    // The lighting pass's per-light arrays, the GL form's uniforms (setOmniLightingUniforms: flat maps
    // at flatBase + index, halves at 2 * index); std140 pads each ivec2 and vec2 entry to 16 bytes.
    char* base = static_cast<char*>(mLightingBlock.map());
    const int n = mLights.shaderLightCount();
    const BlockLayout block{uint32_t(n)};
    const OmniLightSet::LightingArrays a = mLights.lightingArrays(flatBase(), 2);
    std::vector<glm::ivec4> maps(size_t(n), glm::ivec4(0));
    std::vector<glm::vec4> ranges(size_t(n), glm::vec4(0.0f, 1.0f, 0.0f, 0.0f));
    for (size_t i = 0; i < size_t(n) && i < a.maps.size(); ++i) {
        maps[i] = {a.maps[i].x, a.maps[i].y, 0, 0};
        ranges[i] = {a.depthRanges[i].x, a.depthRanges[i].y, 0.0f, 0.0f};
    }
    std::memcpy(base, a.shadowMatrices.data(), 64 * std::min(size_t(n), a.shadowMatrices.size()));
    std::memcpy(base + block.maps, maps.data(), 16 * size_t(n));
    std::memcpy(base + block.ranges, ranges.data(), 16 * size_t(n));

    // The depth passes' slots: flat maps' matrices in Vulkan's depth range, no flip
    // (VulkanFrameBlock::depthFromGl); the halves' data as GL's uniforms (the shader converts z).
    const UniformSlots& slots = mMaps.slots();
    const glm::mat4 z = VulkanFrameBlock::depthFromGl();
    for (const OmniLight& o : mLights.lights()) {
        if (o.kind == OmniMapKind::Flat && o.index < mFlatCount) {
            const glm::mat4 m = z * o.viewProj;
            slots.write(flatSlot(o.index), &m, sizeof m);
        } else if (o.kind == OmniMapKind::Omni && o.index < mOmniCount) {
            for (int half = 0; half < 2; ++half) {
                const ParaboloidPass pass{glm::vec4(o.point.position, float(half)),
                                          glm::vec2(o.point.nearZ, o.point.farZ), mMaxSegmentAngle,
                                          mBeyondRim};
                slots.write(halfSlot(o.index, half), &pass, sizeof pass);
            }
        }
    }
}

void ParaboloidVulkan::createDepthPipelines(const VulkanCompileContext& ctx) {
    // Casters only, depth with the bias of glPolygonOffset(slope, constant), no colour, no fragment stage.
    const PropertySet& p = properties();
    mDepthLayout = createScenePipelineLayout(ctx, {mSets.layout(kDepthSet)});
    const Defines base = ctx.submitter.defines();
    const std::string bias = VulkanDepthMapSet::biasKey(p);
    auto depth = [&](const char* name, const char* vertex, const char* geometry) {
        std::string key = std::string(name) + bias;
        GraphicsPipelineDesc d =
            scenePipeline(ctx, vertex, VulkanDepthMapSet::kDepthFragment, base, mDepthLayout, key, geometry);
        mMaps.depthPipeline(d, p);
        // Both faces, fixed: the warp is not a linear projection (scenes/BackFaceCulling.h).
        d.dynamicCull = false;
        return ctx.pipelines.get(key + "|both-faces", d);
    };
    mFlatDepth = depth("paraboloid-flat-depth", "common/depth.vert", "");
    mParaboloidDepth = depth("paraboloid-depth", "shadowmap/paraboloid_depth.vert", "");
    if (mSplit)
        mSplitDepth =
            depth("paraboloid-split-depth", "shadowmap/cube_depth.vert", "shadowmap/paraboloid_split.geom");
}

void ParaboloidVulkan::compile(const VulkanCompileContext& ctx) {
    release();
    mDevice = ctx.context.device();
    const PropertySet& p = properties();
    mSplit = p.getBool(Paraboloid::kSplit);
    checkFeatures(ctx.context);
    mSize = int(p.getInt(P::kResolution));
    mOmniCount = mLights.omniCount();
    mFlatCount = mLights.flatCount();
    mLayers = flatBase() + mFlatCount;
    mMaxSegmentAngle = ParaboloidSplitting::maxSegmentAngle(mSize);
    mBeyondRim = Paraboloid::beyondRim(mSize, int(p.getInt(P::kPcf)));
    // No shadowed light: a 1 x 1 stand-in (its lookups are compiled out, FLAT_MAPS/OMNI_MAPS).
    mMaps = VulkanDepthMapSet(ctx.context, mLayers > 0 ? uint32_t(mSize) : 1u, uint32_t(std::max(1, mLayers)),
                              uint32_t(mLayers));
    createDescriptors(ctx.context);
    writeBlocks();
    createDepthPipelines(ctx);

    // Lighting pass: the GL technique's defines, permutation for permutation.
    // The depth passes have no shadow to apply: only the lighting pass takes the scene's exceptions.
    const Defines lit = Paraboloid::lightingDefines(ctx.defines(), p, mLights);
    mContact.compile(p, ctx);
    mLightingLayout = createScenePipelineLayout(ctx, mContact.lightingSets({mSets.layout(kLightingSet)}));
    const std::string litPermutation =
        mLighting.build(ctx, "common/scene.vert", "shadowmap/paraboloid_lighting.frag", lit, mLightingLayout,
                        "paraboloid-lighting|");
    const std::string depthKey = definesKey(ctx.submitter.defines());
    setPermutationKey(depthKey + "|" + depthKey + "|" + depthKey + "|" + litPermutation);
}

void ParaboloidVulkan::bindSlot(VulkanFrameContext& ctx, uint32_t slot) {
    ctx.frame.bind(ctx.cmd, mDepthLayout, ctx.frameOffset);
    mMaps.slots().bind(ctx.cmd, mDepthLayout, mSets.set(kDepthSet), slot);
}

void ParaboloidVulkan::renderFlatMaps(VulkanFrameContext& ctx) {
    // As OmniLightsGL's renderOmniFlatMaps: each flat map cleared, its casters culled against its frustum.
    for (const OmniLight& o : mLights.lights()) {
        if (o.kind != OmniMapKind::Flat || o.index >= mFlatCount) continue;
        mMaps.begin(ctx.cmd, size_t(flatBase() + o.index));
        vkCmdBindPipeline(ctx.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mFlatDepth);
        bindSlot(ctx, flatSlot(o.index));
        mCulled += mLights.cullFlatCasters(o, mCulling, mKeep);
        ctx.submitter.draw(ctx.cmd, mDepthLayout, DrawSet::Casters, mKeep);
        vkCmdEndRenderPass(ctx.cmd);
    }
}

void ParaboloidVulkan::drawHemisphere(VulkanFrameContext& ctx, const glm::vec3& light, uint32_t slot) {
    bindSlot(ctx, slot);
    if (mSplit && mSplitting.partition(light, mMaxSegmentAngle, mKeep, mKeepPlain, mKeepSplit) > 0) {
        vkCmdBindPipeline(ctx.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mSplitDepth);
        ctx.submitter.draw(ctx.cmd, mDepthLayout, DrawSet::Casters, mKeepSplit);
        mSplitDrawn += size_t(std::count(mKeepSplit.begin(), mKeepSplit.end(), uint8_t(1)));
        if (std::find(mKeepPlain.begin(), mKeepPlain.end(), uint8_t(1)) == mKeepPlain.end()) return;
        vkCmdBindPipeline(ctx.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mParaboloidDepth);
        ctx.submitter.draw(ctx.cmd, mDepthLayout, DrawSet::Casters, mKeepPlain);
        return;
    }
    vkCmdBindPipeline(ctx.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mParaboloidDepth);
    ctx.submitter.draw(ctx.cmd, mDepthLayout, DrawSet::Casters, mKeep);
}

void ParaboloidVulkan::renderHemispheres(VulkanFrameContext& ctx) {
    for (const OmniLight& o : mLights.lights()) {
        if (o.kind != OmniMapKind::Omni || o.index >= mOmniCount) continue;
        for (int half = 0; half < 2; ++half) {
            mMaps.begin(ctx.cmd, size_t(2 * o.index + half)); // cleared, as DepthLayers::beginLayer
            const size_t kept = mOmniCulling.cullHemisphere(o.point.position, o.point.farZ,
                                                            Paraboloid::hemisphereAxis(half), mKeep);
            mCulled += mOmniCulling.casters() - kept;
            if (kept > 0) { // else the cleared half is the answer: nothing casts into it
                drawHemisphere(ctx, o.point.position, halfSlot(o.index, half));
                ++mHemispheresRendered;
            }
            vkCmdEndRenderPass(ctx.cmd);
        }
    }
}

void ParaboloidVulkan::renderDepth(VulkanFrameContext& ctx) {
    if (mLayers == 0) return; // no light casts: no depth work at all
    renderFlatMaps(ctx);
    renderHemispheres(ctx);
}

void ParaboloidVulkan::execute(VulkanFrameContext& ctx) {
    // The slots and the lighting block were written by compile() and sceneChanged(): nothing per frame.
    mCulled = 0;
    mSplitDrawn = 0;
    mHemispheresRendered = 0;
    const SubmitStats s = DepthLightingFrame::run(
        ctx, [&] { renderDepth(ctx); },
        [&] {
            mContact.bind(ctx.cmd, mLightingLayout);
            mLighting.draw(ctx, mLightingLayout, mSets.set(kLightingSet));
        },
        mContact.prePass(ctx), ContactShadows::kPass);
    mCounters = Paraboloid::counters(s, mLayers > 0 ? mSize : 0, mLayers, mLights, mHemispheresRendered,
                                     mCulled, mSplitDrawn);
}

} // namespace sb
