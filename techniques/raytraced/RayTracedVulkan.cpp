#include "techniques/raytraced/RayTracedVulkan.h"

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "core/Strings.h"
#include "scenes/Motion.h"
#include "scenes/ShadowWork.h"
#include "shading/ShaderLimits.h"
#include "techniques/raytraced/DeviceCount.h"
#include "techniques/raytraced/GuidedRays.h"
#include "techniques/raytraced/RayTraced.h"
#include "techniques/vulkan/ScenePass.h"

namespace sb {

namespace {

/// lighting.frag's FrameState: the ray counter (two words), the frame's index, the frames the history
/// holds.
constexpr VkDeviceSize kFrameStateBytes = kDeviceCountBytes + 2 * sizeof(uint32_t);
/// Where FrameState's frame index lies, in uint32_t words (after the count).
constexpr size_t kFrameWord = kDeviceCountBytes / sizeof(uint32_t);
/// Where the count of accumulated frames stops: past 1 / kHistoryWeight frames the weight no longer
/// depends on it.
constexpr uint32_t kMaxHistoryFrames = 1u << 20;

} // namespace

RayTracedVulkan::RayTracedVulkan() : VulkanTechnique(RayTraced::declaration()) {}

void RayTracedVulkan::propertiesApplied() {
    const RayTraced::Mode mode = RayTraced::mode(properties());
    mGuided = mode == RayTraced::Mode::Guided;
    mutableInfo().passes = RayTraced::passes(mode);
    mutableInfo().effects = RayTraced::effects(mode);
}

RayTracedVulkan::~RayTracedVulkan() {
    if (mLayout) vkDestroyPipelineLayout(mDevice, mLayout, nullptr);
}

std::string RayTracedVulkan::checkCapabilities(const VulkanContext& context) const {
    std::string missing = VulkanTechnique::checkCapabilities(context);
    if (!missing.empty()) return missing;
    std::vector<std::string> features = context.missingRayQueryFeatures();
    if (!context.fragmentStoresAndAtomics()) features.emplace_back("fragmentStoresAndAtomics");
    if (features.empty() && !context.rayQuery()) features.emplace_back("Vulkan 1.2");
    if (features.empty()) return "";
    return name() + " needs the device features " + join(features, " and ") + " (not available on " +
           context.info().name + ", Vulkan " + context.info().apiVersion + "); " + RayTraced::kDriverHint;
}

void RayTracedVulkan::setScene(const Scene& scene) {
    mStructures.reset();
    mRebuild = false;
    if (mGuided) mGuide.setScene(scene, properties());
}

void RayTracedVulkan::sceneChanged(const Scene& scene, uint32_t changes) {
    if (mGuided) mGuide.sceneChanged(scene, properties());
    if (changes) mHistoryFrames = 0;
    if (!(changes & kCastersMoved) || !mStructures) return;
    mStructures->writeInstances(scene);
    mRebuild = true;
}

void RayTracedVulkan::compile(const VulkanCompileContext& ctx) {
    mDevice = ctx.context.device();
    if (!mStructures) mStructures = std::make_unique<AccelerationStructures>(ctx.context, ctx.scene);
    if (mGuided) mGuide.compile(ctx, properties()); // set 2's layout, before the pipeline layout
    if (!mFrameState) {
        mFrameState = VulkanBuffer(ctx.context, kFrameStateBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        std::memset(mFrameState.map(), 0, kFrameStateBytes);
        mTemporal = RayTraced::temporal(properties());
        using D = DescriptorSets;
        D::Bindings bindings = {
            D::binding(0, VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, VK_SHADER_STAGE_FRAGMENT_BIT),
            D::binding(1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT)};
        if (mTemporal)
            bindings.push_back(D::binding(2, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_FRAGMENT_BIT));
        mSets = DescriptorSets(mDevice, {bindings}, "raytraced");
        mSets.writeBuffer(0, 1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, mFrameState.buffer(), kFrameStateBytes);
        if (mTemporal) createHistory(ctx);
        std::vector<VkDescriptorSetLayout> sets{mSets.layout(0)};
        if (mGuided) sets.push_back(mGuide.layout());
        mLayout = createScenePipelineLayout(ctx, sets);
    }
    // The top level is rebuilt in place (same handle) when casters move: written once.
    mSets.writeAccelerationStructure(0, 0, mStructures->topLevel());

    Defines defines = ctx.defines();
    defines["LIGHT_COUNT"] = std::to_string(std::clamp<int>(int(ctx.scene.lights.size()), 1, kMaxLights));
    RayTraced::addModeDefines(properties(), ctx.scene, defines);
    if (mGuided) GuidedRays::addDefines(properties(), defines);
    defines["SB_EYE_RELATIVE_POSITION"] = "1"; // the geometric normal's derivatives (lighting.frag)
    std::string key;
    GraphicsPipelineDesc desc =
        scenePipeline(ctx, "common/scene.vert", "raytraced/lighting.frag", defines, mLayout, key);
    mPipeline.build(ctx.pipelines, key, desc, ctx.targets);
    setPermutationKey(definesKey(defines));
}

void RayTracedVulkan::createHistory(const VulkanCompileContext& ctx) {
    VulkanImageDesc desc;
    desc.width = uint32_t(ctx.targets.width());
    desc.height = uint32_t(ctx.targets.height());
    desc.layers = uint32_t(RayTraced::kHistoryLayers);
    desc.format = VK_FORMAT_R32G32B32A32_SFLOAT;
    desc.usage = VK_IMAGE_USAGE_STORAGE_BIT;
    desc.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
    mHistory = VulkanImage(ctx.context, desc);
    ctx.context.submitNow([&](VkCommandBuffer cmd) {
        transitionImage(cmd, mHistory.image(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                        VK_IMAGE_LAYOUT_GENERAL, desc.layers);
    });
    mSets.writeStorageImage(0, 2, mHistory.view());
    mHistoryFrames = 0;
}

void RayTracedVulkan::recordHistoryFrame(VulkanFrameContext& ctx) {
    const glm::mat4 viewProj = ctx.proj * ctx.view;
    if (viewProj != mHistoryViewProj) mHistoryFrames = 0; // another view: the history shows other surfaces
    mHistoryViewProj = viewProj;
    auto* state = static_cast<uint32_t*>(mFrameState.map());
    state[kFrameWord] = mFrame;
    state[kFrameWord + 1] = mHistoryFrames;
    // The last frame's fragments wrote the layer this one reads (and this one writes the other, which the
    // frame before last read): their writes before this frame's reads and writes.
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_SHADER_READ_BIT;
    barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    vkCmdPipelineBarrier(ctx.cmd, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                         VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0, 1, &barrier, 0, nullptr, 0, nullptr);
    ++mFrame;
    mHistoryFrames = std::min(mHistoryFrames + 1, kMaxHistoryFrames);
}

void RayTracedVulkan::execute(VulkanFrameContext& ctx) {
    mBuiltInFrame = 0;
    if (mRebuild) {
        ctx.passes.begin("structures");
        mStructures->recordTopLevelBuild(ctx.cmd);
        mBuiltInFrame = 1;
        mRebuild = false;
    } else {
        ctx.passes.skip("structures", "nothing moved: the structures built before the first frame hold");
    }
    if (mGuided) recordGuide(ctx);
    // The previous frame has finished (the harness waited for its fence) and this one has not started:
    // the host zeroes the counter the fragments add to.
    zeroDeviceCount(mFrameState.map());
    if (mTemporal) recordHistoryFrame(ctx);
    ctx.passes.begin("lighting");
    ctx.submitter.resetStats();
    if (mGuided) mGuide.bind(ctx.cmd, mLayout);
    drawLitScene(ctx, mPipeline, mLayout, mSets.set(0));
}

Counters RayTracedVulkan::counters() const {
    // Read after the frame's fence (the harness reads counters after the frame it waited for).
    const uint64_t rays = mFrameState ? readDeviceCount(mFrameState.map()) : 0u;
    Counters out = RayTraced::counters(mBuiltInFrame, mStructures ? mStructures->bytes() : 0, rays);
    if (mStructures) {
        const Counters times =
            RayTraced::buildTimes(mStructures->bottomLevelsBuildMs(), mStructures->topLevelBuildMs());
        out.insert(out.end(), times.begin(), times.end());
    }
    if (mGuided)
        for (auto& c : GuidedRays::counters(rays, mGuide.decided(), mGuide.mapTexels())) out.push_back(c);
    return out;
}

void RayTracedVulkan::recordGuide(VulkanFrameContext& ctx) {
    mGuide.resetCount();
    if (const char* reason = ShadowWork::noneNeeded(ctx.scene)) {
        ctx.passes.skip("depth", reason);
        return;
    }
    ctx.passes.begin("depth");
    mGuide.recordDepth(ctx);
}

} // namespace sb
