#include "techniques/occluder/OccluderVulkan.h"

#include <algorithm>
#include <cstring>

#include "techniques/occluder/Occluder.h"
#include "techniques/occluder/OccluderBakeVulkan.h"
#include "techniques/occluder/OccluderMeshCache.h"

namespace sb {

namespace {
// shaders/occluder/scene.vert and lit.frag: GL's bindings, in set 1 on Vulkan.
constexpr uint32_t kTextureBinding = 0, kPlaneBinding = 2, kInstanceBinding = 3, kMatrixBinding = 4,
                   kWorldPlaneBinding = 5, kCandidateBinding = 6, kSectionBinding = 7;

VkSampler createSampler(VkDevice device) {
    // Bilinear magnification (section 5 of the thesis), clamped at the edge; one level, as on GL.
    VkSamplerCreateInfo s{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    s.magFilter = s.minFilter = VK_FILTER_LINEAR;
    s.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    s.addressModeU = s.addressModeV = s.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    s.maxLod = 0.0f;
    VkSampler sampler = VK_NULL_HANDLE;
    VulkanContext::check(vkCreateSampler(device, &s, nullptr, &sampler), "vkCreateSampler (occluder)");
    return sampler;
}
} // namespace

OccluderVulkan::OccluderVulkan() : VulkanTechnique(Occluder::declaration()) {}

OccluderVulkan::~OccluderVulkan() {
    release();
}

void OccluderVulkan::release() {
    if (!mDevice) return;
    vkDestroyPipelineLayout(mDevice, mLayout, nullptr);
    vkDestroySampler(mDevice, mSampler, nullptr);
    mLayout = VK_NULL_HANDLE;
    mSampler = VK_NULL_HANDLE;
    mSets = DescriptorSets();
    mTextures = VulkanImage();
    for (VulkanBuffer* b : {&mPlaneBuffer, &mInstanceBuffer, &mMatrixBuffer, &mSectionBuffer,
                            &mWorldPlaneBuffer, &mCandidateBuffer})
        *b = VulkanBuffer();
}

void OccluderVulkan::setScene(const Scene& scene) {
    mutableInfo().effects = mPlan.setScene(scene, properties());
}

void OccluderVulkan::sceneChanged(const Scene& scene, uint32_t changes) {
    if (mPlan.sceneChanged(scene, changes) && mDevice) writeWorldPlanes();
}

VulkanBuffer OccluderVulkan::storage(VulkanContext& context, const void* data, size_t bytes) const {
    VulkanBuffer b(context, std::max<size_t>(16, bytes), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    std::memset(b.map(), 0, size_t(b.size()));
    if (data && bytes) std::memcpy(b.map(), data, bytes);
    return b;
}

void OccluderVulkan::buildTextures(const VulkanCompileContext& ctx) {
    const int resolution = int(properties().getInt(Occluder::kResolution));
    const std::string device = "vulkan:" + ctx.context.info().name + " " + ctx.context.info().driverInfo;
    const std::vector<OccluderPlan::Texels> layers = mPlan.layers(
        ctx.scene, properties(),
        [&](const Mesh& mesh, const ShadowPlane& plane, const OccluderBakeOptions& options) {
            return OccluderMeshCache::texels(mesh, OccluderPlan::bakeKey(plane, options, device), [&] {
                const std::vector<uint8_t> texels =
                    OccluderBakeVulkan::bake(ctx.context, ctx.shaders, mesh, plane, options);
                return OccluderPlan::finishBake(texels, options.resolution, options.resolution,
                                                options.resolution);
            });
        },
        [](const std::string& path, int size) {
            int w = 0, h = 0;
            const std::vector<uint8_t> texels = OccluderTexels::load(path, w, h);
            return std::make_shared<const std::vector<uint8_t>>(OccluderPlan::resample(texels, w, h, size));
        });
    mLayers = std::max<int>(1, int(layers.size()));
    mResolution = resolution;
    VulkanImageDesc desc;
    desc.width = desc.height = uint32_t(resolution);
    desc.layers = uint32_t(mLayers);
    desc.format = VK_FORMAT_R8_UNORM;
    desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    desc.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
    mTextures = VulkanImage(ctx.context, desc);
    const size_t layerBytes = size_t(resolution) * size_t(resolution);
    VulkanBuffer staging(ctx.context, layerBytes * size_t(mLayers), VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    std::memset(staging.map(), 0, layerBytes * size_t(mLayers));
    for (size_t l = 0; l < layers.size(); ++l)
        std::memcpy(static_cast<char*>(staging.map()) + l * layerBytes, layers[l]->data(), layerBytes);
    ctx.context.submitNow([&](VkCommandBuffer cmd) {
        transitionImage(cmd, mTextures.image(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                        VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, uint32_t(mLayers));
        VkBufferImageCopy copy{};
        copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, uint32_t(mLayers)};
        copy.imageExtent = {uint32_t(resolution), uint32_t(resolution), 1};
        vkCmdCopyBufferToImage(cmd, staging.buffer(), mTextures.image(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                               1, &copy);
        transitionImage(cmd, mTextures.image(), VK_IMAGE_ASPECT_COLOR_BIT,
                        VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                        uint32_t(mLayers));
    });
}

void OccluderVulkan::createBuffers(VulkanContext& context) {
    const auto& planes = mPlan.planes();
    const auto& instances = mPlan.instanceData();
    const auto& matrices = mPlan.matrices();
    const auto& sections = mPlan.sectionTable();
    mPlaneBuffer = storage(context, planes.data(), planes.size() * sizeof(OccluderPlan::GpuPlane));
    mInstanceBuffer = storage(context, instances.data(), instances.size() * sizeof(glm::vec4));
    mMatrixBuffer = storage(context, matrices.data(), matrices.size() * sizeof(glm::vec4));
    mSectionBuffer = storage(context, sections.data(), sections.size() * sizeof(glm::uvec4));
    using D = DescriptorSets;
    constexpr VkShaderStageFlags kVertex = VK_SHADER_STAGE_VERTEX_BIT,
                                 kFragment = VK_SHADER_STAGE_FRAGMENT_BIT;
    constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    mSets = DescriptorSets(
        mDevice,
        {{D::binding(kTextureBinding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kFragment),
          D::binding(kPlaneBinding, kStorage, kVertex), D::binding(kInstanceBinding, kStorage, kVertex),
          D::binding(kMatrixBinding, kStorage, kVertex), D::binding(kWorldPlaneBinding, kStorage, kFragment),
          D::binding(kCandidateBinding, kStorage, kFragment),
          D::binding(kSectionBinding, kStorage, kVertex)}},
        "occluder");
    mSets.writeImage(0, kTextureBinding, mSampler, mTextures.view(),
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    mSets.writeBuffer(0, kPlaneBinding, kStorage, mPlaneBuffer.buffer(), mPlaneBuffer.size());
    mSets.writeBuffer(0, kInstanceBinding, kStorage, mInstanceBuffer.buffer(), mInstanceBuffer.size());
    mSets.writeBuffer(0, kMatrixBinding, kStorage, mMatrixBuffer.buffer(), mMatrixBuffer.size());
    mSets.writeBuffer(0, kSectionBinding, kStorage, mSectionBuffer.buffer(), mSectionBuffer.size());
    writeWorldPlanes();
}

void OccluderVulkan::writeWorldPlanes() {
    std::vector<OccluderPlan::GpuPlane> world;
    std::vector<glm::uvec2> table;
    if (mPlan.receiveAll()) mPlan.worldPlanes(world, table);
    const size_t worldBytes = world.size() * sizeof(OccluderPlan::GpuPlane);
    const size_t tableBytes = table.size() * sizeof(glm::uvec2);
    constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    // Written in place when they fit (the harness waits for each frame's fence: nothing reads them now).
    if (mWorldPlaneBuffer && worldBytes <= mWorldPlaneBuffer.size()) {
        std::memset(mWorldPlaneBuffer.map(), 0, size_t(mWorldPlaneBuffer.size()));
        if (worldBytes) std::memcpy(mWorldPlaneBuffer.map(), world.data(), worldBytes);
    } else {
        mWorldPlaneBuffer = storage(*mContext, world.data(), worldBytes);
        mSets.writeBuffer(0, kWorldPlaneBinding, kStorage, mWorldPlaneBuffer.buffer(),
                          mWorldPlaneBuffer.size());
    }
    if (mCandidateBuffer && tableBytes <= mCandidateBuffer.size()) {
        std::memset(mCandidateBuffer.map(), 0, size_t(mCandidateBuffer.size()));
        if (tableBytes) std::memcpy(mCandidateBuffer.map(), table.data(), tableBytes);
    } else {
        mCandidateBuffer = storage(*mContext, table.data(), tableBytes);
        mSets.writeBuffer(0, kCandidateBinding, kStorage, mCandidateBuffer.buffer(), mCandidateBuffer.size());
    }
}

void OccluderVulkan::compile(const VulkanCompileContext& ctx) {
    release();
    mContext = &ctx.context;
    mDevice = ctx.context.device();
    mPlan.checkVertexComponents(int(ctx.context.properties().limits.maxVertexOutputComponents),
                                ctx.context.info().name);
    buildTextures(ctx);
    mSampler = createSampler(mDevice);
    createBuffers(ctx.context);
    mLayout = createScenePipelineLayout(ctx, {mSets.layout(0)});
    const Defines defines = mPlan.defines(ctx.defines());
    std::string key = "occluder-lighting|";
    GraphicsPipelineDesc desc =
        scenePipeline(ctx, "occluder/scene.vert", "occluder/lit.frag", defines, mLayout, key);
    mPipeline.build(ctx.pipelines, key, desc, ctx.targets);
    setPermutationKey(definesKey(defines));
}

void OccluderVulkan::execute(VulkanFrameContext& ctx) {
    ctx.submitter.resetStats();
    ctx.passes.begin("lighting");
    if (mPlan.perInstance()) {
        mPlan.updateLightSpace();
        const auto& data = mPlan.instanceData();
        if (!data.empty()) std::memcpy(mInstanceBuffer.map(), data.data(), data.size() * sizeof(glm::vec4));
    }
    if (mPlan.textureMatrix()) {
        mPlan.updateMatrices();
        const auto& matrices = mPlan.matrices();
        if (!matrices.empty())
            std::memcpy(mMatrixBuffer.map(), matrices.data(), matrices.size() * sizeof(glm::vec4));
    }
    drawLitScene(ctx, mPipeline, mLayout, mSets.set(0));
    mCounters = mPlan.counters(ctx.scene, ctx.submitter.stats(), mResolution, mLayers);
}

} // namespace sb
