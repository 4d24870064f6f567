#include "techniques/blob/BlobVulkan.h"

#include <algorithm>
#include <cstring>

#include "core/Error.h"
#include "shading/ShaderLimits.h"
#include "techniques/vulkan/ScenePass.h"

namespace sb {

BlobVulkan::BlobVulkan() : VulkanTechnique(Blob::declaration()) {}

BlobVulkan::~BlobVulkan() {
    release();
}

void BlobVulkan::release() {
    if (!mDevice) return;
    vkDestroyPipelineLayout(mDevice, mLayout, nullptr);
    mLayout = VK_NULL_HANDLE;
    mSets = DescriptorSets();
    mBlobBuffer = VulkanBuffer();
    mCapacity = 0;
}

void BlobVulkan::setScene(const Scene& scene) {
    mGround = Blob::groundOf(scene);
    mMeshBounds = Blob::meshBounds(scene);
    mReceiver.setPlanes(mGround ? std::vector<ReceiverPlane>{*mGround} : std::vector<ReceiverPlane>{});
}

void BlobVulkan::reserve(size_t count) {
    if (count <= mCapacity && mBlobBuffer) return;
    // Geometric growth: a frame with a few more blobs does not reallocate. The last frame that read the
    // old buffer has finished (the harness waited for its fence).
    mCapacity = std::max<size_t>({count, 2 * mCapacity, 16});
    const VkDeviceSize bytes = mCapacity * sizeof(Blob::Record);
    mBlobBuffer = VulkanBuffer(*mContext, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    mSets.writeBuffer(0, 0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, mBlobBuffer.buffer(), bytes);
}

void BlobVulkan::compile(const VulkanCompileContext& ctx) {
    release();
    mContext = &ctx.context;
    mDevice = ctx.context.device();
    if (!ctx.context.independentBlend())
        throw Error("blob: the blobs blend colour and visibility differently, which needs the "
                    "independentBlend feature '" +
                        ctx.context.info().name + "' does not offer: unsupported here",
                    ExitCode::Unsupported);
    mSets = DescriptorSets(
        mDevice,
        {{DescriptorSets::binding(0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_VERTEX_BIT)}},
        "blob");
    reserve(0);
    mLayout = createScenePipelineLayout(ctx, {mSets.layout(0)});

    Defines lit = withLightKinds(ctx.submitter.defines(), ctx.scene);
    lit["LIGHT_COUNT"] = std::to_string(std::clamp<int>(int(ctx.scene.lights.size()), 1, kMaxLights));
    std::string litKey = "blob-lit|";
    mLit.build(ctx.pipelines, litKey,
               scenePipeline(ctx, "common/scene.vert", "common/lit.frag", lit, mLayout, litKey), ctx.targets);

    GraphicsPipelineDesc d;
    const ShaderModules modules = ctx.shaders.get(ShaderSources{"blob/blob.vert", "blob/blob.frag", ""}, {});
    d.vertex = modules.vertex;
    d.fragment = modules.fragment;
    d.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_STRIP; // no vertex input: the corners from the index
    d.layout = mLayout;
    VulkanReceiverStencil::darkenState(d, VK_STENCIL_OP_KEEP); // overlapping blobs multiply
    mBlob.build(ctx.pipelines, "blob-blobs|blob/blob.vert+blob/blob.frag", d, ctx.targets);
    mReceiver.compile(ctx, mLayout);
    setPermutationKey(definesKey(lit) + "|blob");
}

void BlobVulkan::renderBlobs(VulkanFrameContext& ctx) {
    reserve(mBlobs.size());
    std::memcpy(mBlobBuffer.map(), mBlobs.data(), mBlobs.size() * sizeof(Blob::Record));
    VkCommandBuffer cmd = ctx.cmd;
    ctx.targets.beginPass(cmd);
    ctx.frame.bind(cmd, mLayout, ctx.frameOffset);
    mReceiver.mark(ctx, 0, 1); // blobs stay on the ground's visible pixels
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mBlob.get(ctx.targets));
    const VkDescriptorSet set = mSets.set(0);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout, 1, 1, &set, 0, nullptr);
    VulkanPush push;
    push.vec = mGround->equation();
    push.colorId = glm::vec4(mGround->albedo, 0.0f);
    vkCmdPushConstants(cmd, mLayout, kPushStages, 0, sizeof push, &push);
    vkCmdDraw(cmd, 4, uint32_t(mBlobs.size()), 0, 0);
    vkCmdEndRenderPass(cmd);
}

void BlobVulkan::execute(VulkanFrameContext& ctx) {
    ctx.submitter.resetStats();
    ctx.passes.begin("lighting");
    drawLitScene(ctx, mLit, mLayout);

    ctx.passes.begin("blobs");
    mBlobs.clear();
    if (mGround) Blob::fitAll(ctx.scene, *mGround, mMeshBounds, properties(), mBlobs);
    if (!mBlobs.empty()) renderBlobs(ctx);
    mCounters = Blob::counters(ctx.submitter.stats(), mBlobs.size());
}

} // namespace sb
