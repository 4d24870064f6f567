#include "techniques/shadowmap/VsmVulkan.h"

namespace sb {

VsmVulkan::VsmVulkan() : VulkanTechnique(Vsm::declaration()) {}

void VsmVulkan::setScene(const Scene& scene) {
    mMaps.fits().setScene(scene, properties());
}

void VsmVulkan::compile(const VulkanCompileContext& ctx) {
    const PropertySet& p = properties();
    const int resolution = int(p.getInt(Vsm::kResolution));
    mMaps.fits().setReceiverBackground(p.getBool(Vsm::kReceiverBackground));
    mMaps.fits().setViewCull(p.getBool(Vsm::kCull));
    // The border the filter's reads need: the blur's radius and the bilinear footprint's texel.
    mMaps.fits().fit(ctx.scene, resolution, int(p.getInt(Vsm::kBlur)) / 2 + 1);
    VulkanMomentMaps::Settings s;
    s.format = VK_FORMAT_R32G32_SFLOAT; // GL_RG32F
    s.resolution = resolution;
    s.depthDefines = ctx.submitter.defines();
    s.depthDefines["VSM"] = "";
    s.lightingFragment = "shadowmap/vsm.frag";
    s.lightingDefines = ctx.defines();
    s.params = {float(p.getFloat(Vsm::kMinVariance)), float(p.getFloat(Vsm::kBleedReduction))};
    s.clear = {1.0f, 1.0f, 0.0f, 0.0f}; // the moments of d = 1: nothing in front of the far end
    s.blur = {.width = int(p.getInt(Vsm::kBlur)), .logSpace = false};
    setPermutationKey(mMaps.compile(ctx, s));
}

void VsmVulkan::execute(VulkanFrameContext& ctx) {
    mCounters = mMaps.renderFrame(ctx);
}

} // namespace sb
