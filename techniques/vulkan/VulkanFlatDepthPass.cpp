#include "techniques/vulkan/VulkanFlatDepthPass.h"

#include <utility>

#include "techniques/vulkan/ScenePass.h"
#include "techniques/vulkan/VulkanTechnique.h"

namespace sb {

VulkanFlatDepthPass::VulkanFlatDepthPass(const VulkanCompileContext& ctx, const std::string& name,
                                         uint32_t size, uint32_t layers, double biasSlope,
                                         double biasConstant)
    : mDevice(ctx.context.device()), mMaps(ctx.context, size, layers, layers) {
    mMaps.createSlots(ctx.context, sizeof(glm::mat4), layers);
    using D = DescriptorSets;
    mSet = DescriptorSets(
        mDevice, {{D::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, VK_SHADER_STAGE_VERTEX_BIT)}},
        name.c_str());
    mSet.writeBuffer(0, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, mMaps.slots().buffer(),
                     mMaps.slots().bytes());
    mLayout = createScenePipelineLayout(ctx, {mSet.layout(0)});
    std::string key = name + "-depth" + VulkanDepthMapSet::biasKey(biasSlope, biasConstant);
    GraphicsPipelineDesc desc = scenePipeline(ctx, "common/depth.vert", VulkanDepthMapSet::kDepthFragment,
                                              ctx.submitter.defines(), mLayout, key);
    mMaps.depthPipeline(desc, biasSlope, biasConstant);
    mPipeline = ctx.pipelines.get(key, desc);
}

VulkanFlatDepthPass::~VulkanFlatDepthPass() {
    release();
}

VulkanFlatDepthPass::VulkanFlatDepthPass(VulkanFlatDepthPass&& other) noexcept {
    *this = std::move(other);
}

VulkanFlatDepthPass& VulkanFlatDepthPass::operator=(VulkanFlatDepthPass&& other) noexcept {
    if (this == &other) return *this;
    release();
    mDevice = std::exchange(other.mDevice, VK_NULL_HANDLE);
    mMaps = std::move(other.mMaps);
    mSet = std::move(other.mSet);
    mLayout = std::exchange(other.mLayout, VK_NULL_HANDLE);
    mPipeline = std::exchange(other.mPipeline, VK_NULL_HANDLE);
    mKeep = std::exchange(other.mKeep, {});
    return *this;
}

void VulkanFlatDepthPass::release() {
    if (!mDevice) return;
    vkDestroyPipelineLayout(mDevice, mLayout, nullptr);
    mLayout = VK_NULL_HANDLE;
    mPipeline = VK_NULL_HANDLE;
    mSet = DescriptorSets();
    mMaps = VulkanDepthMapSet();
    mDevice = VK_NULL_HANDLE;
}

void VulkanFlatDepthPass::writeLights(const FlatLightFits& lights) const {
    for (size_t i = 0; i < lights.viewProj().size() && i < mMaps.layers(); ++i) {
        const glm::mat4 m = VulkanFrameBlock::depthFromGl() * lights.viewProj()[i];
        mMaps.slots().write(i, &m, sizeof m);
    }
}

size_t VulkanFlatDepthPass::record(VulkanFrameContext& ctx, const FlatLightFits& lights,
                                   const InstanceCulling& culling, const ViewCull* view) {
    size_t culled = 0;
    for (size_t i = 0; i < lights.viewProj().size() && i < mMaps.layers(); ++i) {
        if (!lights.castsShadow(i)) continue;
        culled += lights.cullCasters(i, culling, mKeep, view);
        mMaps.begin(ctx.cmd, i);
        vkCmdBindPipeline(ctx.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline);
        ctx.frame.bind(ctx.cmd, mLayout, ctx.frameOffset);
        mMaps.slots().bind(ctx.cmd, mLayout, mSet.set(0), i);
        // The nearest caster per texel: closed casters' back faces can go (scenes/BackFaceCulling.h).
        ctx.submitter.drawCulled(ctx.cmd, mLayout, DrawSet::Casters, {lights.viewProj()[i], false}, false,
                                 mKeep);
        vkCmdEndRenderPass(ctx.cmd);
    }
    return culled;
}

} // namespace sb
