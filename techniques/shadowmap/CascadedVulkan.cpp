#include "techniques/shadowmap/CascadedVulkan.h"

#include <cstring>

#include "core/Error.h"
#include "techniques/ContactShadows.h"
#include "techniques/DepthLightingFrame.h"
#include "techniques/ShadowMapProperties.h"
#include "techniques/shadowmap/Cascaded.h"
#include "techniques/vulkan/ScenePass.h"

namespace sb {

namespace {
using P = ShadowMapProperties;

/// std140 offsets of cascaded_lighting.frag's CascadedBlock for `slots` slots: three vec4, a uint, then
/// mat4 uSlotMatrix[] and int uSlotLayer[] (16 bytes per element).
struct BlockLayout {
    explicit BlockLayout(uint32_t slots) : matrices(64), layers(64 + 64 * slots), size(64 + 80 * slots) {}
    static constexpr uint32_t splitFar = 0, bandStart = 16, bandScale = 32, emptySlots = 48;
    uint32_t matrices, layers, size;
};

} // namespace

CascadedVulkan::CascadedVulkan() : VulkanTechnique(Cascaded::declaration()) {}

CascadedVulkan::~CascadedVulkan() {
    release();
}

void CascadedVulkan::propertiesApplied() {
    mutableInfo().passes = Cascaded::passes(properties());
}

void CascadedVulkan::release() {
    if (!mDevice) return;
    vkDestroyPipelineLayout(mDevice, mDepthLayout, nullptr);
    vkDestroyPipelineLayout(mDevice, mLightingLayout, nullptr);
    mSets = DescriptorSets();
    mDepthLayout = mLightingLayout = VK_NULL_HANDLE;
    mDepthPipeline = VK_NULL_HANDLE; // owned by the pipeline cache
    mMaps = VulkanDepthMapSet();
    mLightingBlock = VulkanBuffer();
}

void CascadedVulkan::setScene(const Scene& scene) {
    mPlan.setScene(scene, int(properties().getInt(Cascaded::kCascades)));
    mRange.reset();
}

void CascadedVulkan::createDescriptors(VulkanContext& context) {
    // As DepthLayers on GL: hardware compare (LEQUAL) with LINEAR, the four comparison results filtered.
    const VkSampler sampler = mMaps.addSampler(true);
    mMaps.createSlots(context, sizeof(glm::mat4), uint32_t(mSlots));
    // Set 1 of the depth pass: the slot's matrix, one dynamic slot per slot (LightPass). Set 1 of the
    // lighting pass: CascadedBlock and the map array.
    using D = DescriptorSets;
    mSets = DescriptorSets(
        mDevice,
        {{D::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, VK_SHADER_STAGE_VERTEX_BIT)},
         {D::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT),
          D::binding(1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT)}},
        "cascaded");
    const BlockLayout block{uint32_t(mSlots)};
    mLightingBlock = VulkanBuffer(context, block.size, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    std::memset(mLightingBlock.map(), 0, block.size);
    mSets.writeBuffer(kDepthSet, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, mMaps.slots().buffer(),
                      mMaps.slots().bytes());
    mSets.writeBuffer(kLightingSet, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, mLightingBlock.buffer(),
                      block.size);
    mSets.writeImage(kLightingSet, 1, sampler, mMaps.view(), VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
}

void CascadedVulkan::createPipelines(const VulkanCompileContext& ctx) {
    const PropertySet& p = properties();
    // Depth pass: casters only, depth clamped, with the bias of glPolygonOffset(slope, constant), no colour,
    // no fragment stage.
    mDepthLayout = createScenePipelineLayout(ctx, {mSets.layout(kDepthSet)});
    const Defines base = ctx.submitter.defines();
    std::string depthKey = "cascaded-depth" + VulkanDepthMapSet::biasKey(p);
    GraphicsPipelineDesc depth = scenePipeline(ctx, "common/depth.vert", VulkanDepthMapSet::kDepthFragment,
                                               base, mDepthLayout, depthKey);
    depth.depthClamp = true;
    mMaps.depthPipeline(depth, p);
    mDepthPipeline = ctx.pipelines.get(depthKey, depth);

    // Lighting pass: the GL form's defines, permutation for permutation.
    // The depth pass has no shadow to apply: only the lighting pass takes the scene's exceptions.
    const Defines lit = mPlan.lightingDefines(ctx.defines(), p);
    // contact=on: the view depth's set as set 2 (ViewDepthVulkan::kLightingSet).
    std::vector<VkDescriptorSetLayout> sets{mSets.layout(kLightingSet)};
    if (ContactShadows::enabled(p)) sets.push_back(mViewDepth.lightingSetLayout());
    mLightingLayout = createScenePipelineLayout(ctx, sets);
    const std::string litPermutation =
        mLighting.build(ctx, "common/scene.vert", "shadowmap/cascaded_lighting.frag", lit, mLightingLayout,
                        "cascaded-lighting|");
    setPermutationKey(definesKey(base) + "|" + litPermutation);
}

void CascadedVulkan::compile(const VulkanCompileContext& ctx) {
    release();
    mDevice = ctx.context.device();
    if (!ctx.context.depthClamp())
        throw Error("cascaded: the Vulkan device '" + ctx.context.info().name +
                        "' has no depthClamp (GL_DEPTH_CLAMP of the depth pass, which keeps casters nearer "
                        "the light than a cascade's box); run it with --api gl",
                    ExitCode::Unsupported);
    mSize = int(properties().getInt(P::kResolution));
    mSlots = mPlan.slotCount();
    mMaps = VulkanDepthMapSet(ctx.context, uint32_t(mSize), uint32_t(mSlots), uint32_t(mSlots));
    createDescriptors(ctx.context);
    if (Cascaded::viewDepth(properties())) mViewDepth.compile(ctx); // before the lighting pipeline's layout
    if (Cascaded::sampleDistribution(properties())) mRange.compile(ctx, mViewDepth);
    createPipelines(ctx);
}

void CascadedVulkan::drawMap(VulkanFrameContext& ctx, size_t slot) {
    // The slot's matrix: Vulkan's depth range, no flip (VulkanFrameBlock::depthFromGl). The previous
    // frame's fence has been waited for, so no slot is in flight.
    const glm::mat4 m = VulkanFrameBlock::depthFromGl() * mPlan.slotViewProj()[slot];
    mMaps.slots().write(slot, &m, sizeof m);
    mMaps.begin(ctx.cmd, slot);
    vkCmdBindPipeline(ctx.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mDepthPipeline);
    ctx.frame.bind(ctx.cmd, mDepthLayout, ctx.frameOffset);
    mMaps.slots().bind(ctx.cmd, mDepthLayout, mSets.set(kDepthSet), slot);
    // Clamped depth: a near side cutting a caster does not open it.
    ctx.submitter.drawCulled(ctx.cmd, mDepthLayout, DrawSet::Casters, {mPlan.slotViewProj()[slot], true},
                             false, mKeep);
    vkCmdEndRenderPass(ctx.cmd);
}

void CascadedVulkan::renderDepth(VulkanFrameContext& ctx, glm::vec2 samples) {
    mPlan.fit(ctx.view, ctx.proj, properties(), mSize, samples);
    mPlan.planDepth(mKeep, [&](size_t slot) { drawMap(ctx, slot); });
}

void CascadedVulkan::writeLightingBlock() {
    char* base = static_cast<char*>(mLightingBlock.map());
    const BlockLayout block{uint32_t(mSlots)};
    const CascadedMaps::SplitValues v = mPlan.splitValues(properties());
    std::memcpy(base + BlockLayout::splitFar, &v.splitFar, sizeof(glm::vec4));
    std::memcpy(base + BlockLayout::bandStart, &v.bandStart, sizeof(glm::vec4));
    std::memcpy(base + BlockLayout::bandScale, &v.bandScale, sizeof(glm::vec4));
    const uint32_t empty = mPlan.emptySlots();
    std::memcpy(base + BlockLayout::emptySlots, &empty, sizeof empty);
    const auto& shadow = mPlan.slotShadow();
    const auto& layers = mPlan.slotLayer();
    for (size_t i = 0; i < size_t(mSlots) && i < shadow.size(); ++i) {
        std::memcpy(base + block.matrices + 64 * i, &shadow[i], sizeof(glm::mat4));
        const int32_t layer = layers[i];
        std::memcpy(base + block.layers + 16 * i, &layer, sizeof layer);
    }
}

void CascadedVulkan::execute(VulkanFrameContext& ctx) {
    const PropertySet& p = properties();
    glm::vec2 samples(1.0f, 0.0f); // fit=sdsm: the reduction's view-depth interval
    // The view depth pre-pass, once for both readers: fit=sdsm's reduction (which records it, the first
    // frame's in a submission of its own) and contact=on's march.
    std::function<void()> viewDepth;
    if (Cascaded::sampleDistribution(p))
        viewDepth = [&] { samples = mRange.run(ctx, mViewDepth); };
    else if (ContactShadows::enabled(p))
        viewDepth = [&] { mViewDepth.record(ctx, ctx.cmd); };
    const SubmitStats s = DepthLightingFrame::run(
        ctx, [&] { renderDepth(ctx, samples); },
        [&] {
            writeLightingBlock();
            if (ContactShadows::enabled(p))
                mViewDepth.bindForLighting(ctx.cmd, mLightingLayout, ContactShadows::block(p));
            mLighting.draw(ctx, mLightingLayout, mSets.set(kLightingSet));
        },
        viewDepth, Cascaded::viewDepthPass(p));
    mCounters = mPlan.counters(s, mSize, ctx.scene, properties());
}

} // namespace sb
