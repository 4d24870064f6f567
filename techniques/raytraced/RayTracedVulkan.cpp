#include "techniques/raytraced/RayTracedVulkan.h"

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "core/Strings.h"
#include "scenes/Motion.h"
#include "shading/ShaderLimits.h"
#include "techniques/raytraced/RayTraced.h"
#include "techniques/vulkan/ScenePass.h"

namespace sb {

RayTracedVulkan::RayTracedVulkan() : VulkanTechnique(RayTraced::declaration()) {}

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

void RayTracedVulkan::setScene(const Scene&) {
    mStructures.reset();
    mRebuild = false;
}

void RayTracedVulkan::sceneChanged(const Scene& scene, uint32_t changes) {
    if (!(changes & kCastersMoved) || !mStructures) return;
    mStructures->writeInstances(scene);
    mRebuild = true;
}

void RayTracedVulkan::compile(const VulkanCompileContext& ctx) {
    mDevice = ctx.context.device();
    if (!mStructures) mStructures = std::make_unique<AccelerationStructures>(ctx.context, ctx.scene);
    if (!mRayCount) {
        mRayCount = VulkanBuffer(ctx.context, sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        std::memset(mRayCount.map(), 0, sizeof(uint32_t));
        using D = DescriptorSets;
        mSets = DescriptorSets(
            mDevice,
            {{D::binding(0, VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, VK_SHADER_STAGE_FRAGMENT_BIT),
              D::binding(1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT)}},
            "raytraced");
        mSets.writeBuffer(0, 1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, mRayCount.buffer(), sizeof(uint32_t));
        mLayout = createScenePipelineLayout(ctx, {mSets.layout(0)});
    }
    // The top level is rebuilt in place (same handle) when casters move: written once.
    mSets.writeAccelerationStructure(0, 0, mStructures->topLevel());

    Defines defines = ctx.defines();
    defines["LIGHT_COUNT"] = std::to_string(std::clamp<int>(int(ctx.scene.lights.size()), 1, kMaxLights));
    RayTraced::addModeDefines(RayTraced::mode(properties()), defines);
    defines["SB_EYE_RELATIVE_POSITION"] = "1"; // the geometric normal's derivatives (lighting.frag)
    std::string key;
    GraphicsPipelineDesc desc =
        scenePipeline(ctx, "common/scene.vert", "raytraced/lighting.frag", defines, mLayout, key);
    mPipeline.build(ctx.pipelines, key, desc, ctx.targets);
    setPermutationKey(definesKey(defines));
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
    // The previous frame has finished (the harness waited for its fence) and this one has not started:
    // the host zeroes the counter the fragments add to.
    *static_cast<uint32_t*>(mRayCount.map()) = 0;
    ctx.passes.begin("lighting");
    ctx.submitter.resetStats();
    drawLitScene(ctx, mPipeline, mLayout, mSets.set(0));
}

Counters RayTracedVulkan::counters() const {
    // Read after the frame's fence (the harness reads counters after the frame it waited for).
    const uint32_t rays = mRayCount ? *static_cast<const uint32_t*>(mRayCount.map()) : 0u;
    Counters out = RayTraced::counters(mBuiltInFrame, mStructures ? mStructures->bytes() : 0, rays);
    if (mStructures) {
        const Counters times =
            RayTraced::buildTimes(mStructures->bottomLevelsBuildMs(), mStructures->topLevelBuildMs());
        out.insert(out.end(), times.begin(), times.end());
    }
    return out;
}

} // namespace sb
