#include "techniques/raytraced/GuideMapsVulkan.h"

#include <algorithm>
#include <cstring>

#include <glm/glm.hpp>

#include "scenes/LightFit.h"
#include "shading/ShaderLimits.h"
#include "techniques/ShadowMapProperties.h"
#include "techniques/raytraced/DeviceCount.h"
#include "techniques/raytraced/GuidedRays.h"
#include "techniques/vulkan/VulkanTechnique.h"

namespace sb {

namespace {

/// std140 offsets of guided.glsl's GuidedBlock for `lights` lights.
struct BlockLayout {
    explicit BlockLayout(uint32_t lights) : light(64 * lights), params(80 * lights), size(params + 16) {}
    uint32_t light, params, size;
};

/// The maps frame what `shadowmap`'s default frames: the casters, with its margin.
void fit(FlatLightFits& lights, const Scene& scene, const PropertySet& p) {
    lights.setScene(scene, "raytraced", LightFit{}, int(p.getInt(ShadowMapProperties::kResolution)),
                    FlatLightFits::PointLights::Unmapped);
}

} // namespace

void GuideMapsVulkan::setScene(const Scene& scene, const PropertySet& p) {
    fit(mLights, scene, p);
    mCulling.setScene(scene);
    mDirectional.clear();
    for (size_t i = 0; i < mLights.size(); ++i)
        mDirectional.push_back(scene.lights[i].type == LightType::Directional);
}

void GuideMapsVulkan::sceneChanged(const Scene& scene, const PropertySet& p) {
    setScene(scene, p);
    writeBlock();
    mDepth.writeLights(mLights);
}

void GuideMapsVulkan::compile(const VulkanCompileContext& ctx, const PropertySet& p) {
    const uint32_t layers = uint32_t(std::clamp<size_t>(mLights.size(), 1, kMaxLights));
    mSize = int(p.getInt(ShadowMapProperties::kResolution));
    mMargin = float(p.getFloat(GuidedRays::kMargin));
    // No depth bias: the rule compares each tap with the receiver's own plane instead (GuidedRays.h).
    mDepth = VulkanFlatDepthPass(ctx, "raytraced-guided", uint32_t(mSize), layers, 0.0, 0.0);
    mDepth.writeLights(mLights);
    const VkSampler nearest = mDepth.maps().addSampler(false);

    const BlockLayout block{layers};
    mBlock = VulkanBuffer(ctx.context, block.size, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    std::memset(mBlock.map(), 0, block.size);
    writeBlock();
    mDecided = VulkanBuffer(ctx.context, kDeviceCountBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    zeroDeviceCount(mDecided.map());

    using D = DescriptorSets;
    mSets = DescriptorSets(
        ctx.context.device(),
        {{D::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT),
          D::binding(1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT),
          D::binding(2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT)}},
        "raytraced guided");
    mSets.writeBuffer(0, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, mBlock.buffer(), block.size);
    mSets.writeImage(0, 1, nearest, mDepth.maps().view(), VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
    mSets.writeBuffer(0, 2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, mDecided.buffer(), kDeviceCountBytes);
}

void GuideMapsVulkan::writeBlock() const {
    char* base = static_cast<char*>(mBlock.map());
    if (!base) return;
    const size_t layers = mDepth.maps().layers();
    const BlockLayout block{uint32_t(layers)};
    for (size_t i = 0; i < mLights.size() && i < layers; ++i) {
        std::memcpy(base + 64 * i, &mLights.shadowMatrices()[i], sizeof(glm::mat4));
        const glm::vec4 light(FlatLightFits::texelWorldSize(mLights.viewProj()[i], mSize),
                              mLights.castsShadow(i) ? 1.0f : 0.0f, mDirectional[i] ? 1.0f : 0.0f, 0.0f);
        std::memcpy(base + block.light + 16 * i, &light, sizeof light);
    }
    const glm::vec4 params(mMargin, GuidedRays::kDepthSteps / 16777216.0f, 0.0f, 0.0f);
    std::memcpy(base + block.params, &params, sizeof params);
}

void GuideMapsVulkan::recordDepth(VulkanFrameContext& ctx) {
    mDepth.record(ctx, mLights, mCulling);
}

void GuideMapsVulkan::resetCount() const {
    // The previous frame has finished (the harness waited for its fence) and this one has not started.
    if (mDecided) zeroDeviceCount(mDecided.map());
}

void GuideMapsVulkan::bind(VkCommandBuffer cmd, VkPipelineLayout layout) const {
    const VkDescriptorSet set = mSets.set(0);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 2, 1, &set, 0, nullptr);
}

uint64_t GuideMapsVulkan::decided() const {
    return mDecided ? readDeviceCount(mDecided.map()) : 0u;
}

double GuideMapsVulkan::mapTexels() const {
    return double(mSize) * double(mSize) * double(mLights.shadowed());
}

} // namespace sb
