#include "techniques/shadowmap/MomentMapVulkan.h"

#include "techniques/ContactShadows.h"

namespace sb {

namespace {

/// MomentMapGL's GL formats, one for one.
VkFormat vulkanFormat(MomentMapKind::Format f) {
    switch (f) {
    case MomentMapKind::Format::R32F:
        return VK_FORMAT_R32_SFLOAT;
    case MomentMapKind::Format::RG32F:
        return VK_FORMAT_R32G32_SFLOAT;
    case MomentMapKind::Format::RGBA16Unorm:
        return VK_FORMAT_R16G16B16A16_UNORM;
    case MomentMapKind::Format::RGBA32F:
        return VK_FORMAT_R32G32B32A32_SFLOAT;
    }
    return VK_FORMAT_R32G32B32A32_SFLOAT;
}

} // namespace

MomentMapVulkan::MomentMapVulkan(const MomentMapKind& kind)
    : VulkanTechnique(kind.declaration()), mKind(kind), mMaps(kind.declaration().name) {}

void MomentMapVulkan::propertiesApplied() {
    mutableInfo().passes = ContactShadows::passes(properties(), mKind.declaration().passes);
}

void MomentMapVulkan::setScene(const Scene& scene) {
    mMaps.fits().setScene(scene, properties());
}

void MomentMapVulkan::compile(const VulkanCompileContext& ctx) {
    const PropertySet& p = properties();
    const int resolution = int(p.getInt(MomentMapKind::kResolution));
    mMaps.fits().setReceiverBackground(p.getBool(MomentMapKind::kReceiverBackground));
    mMaps.fits().setViewCull(p.getBool(MomentMapKind::kCull));
    // The border the filter's reads need: the blur's radius and the bilinear footprint's texel.
    mMaps.fits().fit(ctx.scene, resolution, int(p.getInt(MomentMapKind::kBlur)) / 2 + 1);
    VulkanMomentMaps::Settings s;
    s.format = vulkanFormat(mKind.format(p));
    s.resolution = resolution;
    s.depthDefines = ctx.submitter.defines();
    mKind.depthDefines(p, s.depthDefines);
    s.lightingFragment = mKind.lightingFragment;
    s.lightingDefines = ctx.defines();
    mKind.lightingDefines(p, s.lightingDefines);
    ContactShadows::addDefines(p, s.lightingDefines);
    const std::vector<float> params = mKind.params(p);
    for (size_t i = 0; i < params.size() && i < 2; ++i) s.params[int(i)] = params[i];
    s.clear = mKind.noOccluder(p);
    const float exponent = mKind.logSpaceExponent(p);
    s.blur = {.width = int(p.getInt(MomentMapKind::kBlur)),
              .logSpace = exponent > 0.0f,
              .exponent = exponent > 0.0f ? exponent : 1.0f};
    mMaps.contact().compile(p, ctx);
    setPermutationKey(mMaps.compile(ctx, s));
}

void MomentMapVulkan::execute(VulkanFrameContext& ctx) {
    mCounters = mMaps.renderFrame(ctx);
}

} // namespace sb
