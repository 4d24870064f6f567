#include "techniques/shadowmap/PcssVulkan.h"

#include <algorithm>
#include <cstring>

#include "techniques/ContactShadows.h"
#include "techniques/DepthLightingFrame.h"
#include "techniques/ShadowMapProperties.h"
#include "techniques/shadowmap/PoissonDisk.h"
#include "techniques/vulkan/ScenePass.h"

namespace sb {

namespace {
using P = ShadowMapProperties;

/// std140 offsets of shadowmap/pcss.frag's ShadowMapBlock for `lights` lights.
struct BlockLayout {
    explicit BlockLayout(uint32_t lights)
        : light(64 * lights), search(80 * lights), blockerKernel(96 * lights),
          filterKernel(blockerKernel + 16 * Pcss::kMaxTaps), taps(filterKernel + 16 * Pcss::kMaxTaps),
          size(taps + 16) {}
    uint32_t light, search, blockerKernel, filterKernel, taps, size;
};

/// The search's and the filter's sampling: clamped to an opaque white border (depth 1, no caster
/// outside the map, as GL's border colour), nearest raw depths or a linear LEQUAL comparison.
LayerPasses::Sampling sampling(bool compare) {
    LayerPasses::Sampling s;
    s.filter = compare ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
    s.whiteBorder = true;
    s.compare = compare;
    return s;
}
} // namespace

PcssVulkan::PcssVulkan() : VulkanTechnique(Pcss::declaration()) {}

PcssVulkan::~PcssVulkan() {
    release();
}

void PcssVulkan::release() {
    if (!mDevice) return;
    vkDestroyPipelineLayout(mDevice, mLightingLayout, nullptr);
    mSets = DescriptorSets();
    mLightingLayout = VK_NULL_HANDLE;
    mDepth = VulkanFlatDepthPass();
}

void PcssVulkan::propertiesApplied() {
    mutableInfo().passes = ContactShadows::passes(properties(), Pcss::declaration().passes);
}

void PcssVulkan::setScene(const Scene& scene) {
    mLights.setScene(scene, "pcss", properties());
    mCulling.setScene(scene);
}

void PcssVulkan::sceneChanged(const Scene& scene, uint32_t) {
    setScene(scene);
    fitLightSizes(scene);
    writeBlocks();
}

void PcssVulkan::fitLightSizes(const Scene& scene) {
    mParams.clear();
    for (size_t i = 0; i < mLights.size(); ++i)
        mParams.push_back(Pcss::lightParams(scene, scene.lights[i], mLights.viewProj()[i],
                                            float(properties().getFloat(Pcss::kLightSize))));
}

void PcssVulkan::createDescriptors(VulkanContext& context) {
    const VkSampler search = mDepth.maps().addSampler(sampling(false), "pcss");
    const VkSampler compare = mDepth.maps().addSampler(sampling(true), "pcss");
    // Set 1 of the lighting pass: the block and the map through each sampler.
    using D = DescriptorSets;
    mSets = DescriptorSets(
        mDevice,
        {{D::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                     VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT),
          D::binding(1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT),
          D::binding(2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT)}},
        "pcss");
    const BlockLayout block{uint32_t(mLayers)};
    mLightingBlock = VulkanBuffer(context, block.size, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    std::memset(mLightingBlock.map(), 0, block.size);
    mSets.writeBuffer(0, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, mLightingBlock.buffer(), block.size);
    const VkImageLayout layout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;
    mSets.writeImage(0, 1, search, mDepth.maps().view(), layout);
    mSets.writeImage(0, 2, compare, mDepth.maps().view(), layout);
}

void PcssVulkan::writeBlocks() {
    char* base = static_cast<char*>(mLightingBlock.map());
    if (!base) return;
    const BlockLayout block{uint32_t(mLayers)};
    const auto& shadow = mLights.shadowMatrices();
    for (size_t i = 0; i < shadow.size() && i < size_t(mLayers); ++i)
        std::memcpy(base + 64 * i, &shadow[i], sizeof(glm::mat4));
    for (size_t i = 0; i < mParams.size() && i < size_t(mLayers); ++i) {
        const glm::vec4 light = Pcss::lightVector(mParams[i]), search = Pcss::searchVector(mParams[i]);
        std::memcpy(base + block.light + 16 * i, &light, sizeof light);
        std::memcpy(base + block.search + 16 * i, &search, sizeof search);
    }
    for (size_t k = 0; k < mBlockerKernel.size() && k < size_t(Pcss::kMaxTaps); ++k)
        std::memcpy(base + block.blockerKernel + 16 * k, &mBlockerKernel[k], sizeof(glm::vec2));
    for (size_t k = 0; k < mFilterKernel.size() && k < size_t(Pcss::kMaxTaps); ++k)
        std::memcpy(base + block.filterKernel + 16 * k, &mFilterKernel[k], sizeof(glm::vec2));
    const glm::ivec2 taps(int(mBlockerKernel.size()), int(mFilterKernel.size()));
    std::memcpy(base + block.taps, &taps, sizeof taps);
    mDepth.writeLights(mLights);
}

void PcssVulkan::compile(const VulkanCompileContext& ctx) {
    release();
    mDevice = ctx.context.device();
    const PropertySet& p = properties();
    mLayers = std::max<int>(1, int(mLights.size()));
    mSize = int(p.getInt(P::kResolution));
    // Depth pass: casters only, depth with the bias of glPolygonOffset(slope, constant).
    mDepth = VulkanFlatDepthPass(ctx, "pcss", uint32_t(mSize), uint32_t(mLayers), p.getFloat(P::kBiasSlope),
                                 p.getFloat(P::kBiasConstant));
    createDescriptors(ctx.context);
    mBlockerKernel = PoissonDisk::generate(int(p.getInt(Pcss::kBlockerTaps)));
    mFilterKernel = PoissonDisk::generate(int(p.getInt(Pcss::kFilterTaps)), Pcss::filterSeed());
    fitLightSizes(ctx.scene);
    writeBlocks();

    const Defines base = ctx.submitter.defines();

    // Lighting pass: the GL form's defines.
    Defines lit = ctx.defines();
    lit["SHADOW_MAP"] = "";
    lit["LIGHT_COUNT"] = std::to_string(mLayers);
    ContactShadows::addDefines(p, lit);
    mContact.compile(p, ctx);
    mLightingLayout = createScenePipelineLayout(ctx, mContact.lightingSets({mSets.layout(0)}));
    const std::string litPermutation = mLighting.build(ctx, "common/scene.vert", "shadowmap/pcss.frag", lit,
                                                       mLightingLayout, "pcss-lighting|");
    setPermutationKey(definesKey(base) + "|" + litPermutation);
}

void PcssVulkan::execute(VulkanFrameContext& ctx) {
    const SubmitStats s = DepthLightingFrame::run(
        ctx, [&] { mCulled = mDepth.record(ctx, mLights, mCulling); },
        [&] {
            mContact.bind(ctx.cmd, mLightingLayout);
            mLighting.draw(ctx, mLightingLayout, mSets.set(0));
        },
        mContact.prePass(ctx), ContactShadows::kPass);
    mCounters =
        Pcss::counters(s, mSize, mLights, mCulled, mBlockerKernel.size(), mFilterKernel.size(), mParams);
}

} // namespace sb
