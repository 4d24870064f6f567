#include "techniques/shadowmap/MsmVulkan.h"

namespace sb {

MsmVulkan::MsmVulkan() : VulkanTechnique(Msm::declaration()) {}

void MsmVulkan::setScene(const Scene& scene) {
    mMaps.fits().setScene(scene, properties());
}

void MsmVulkan::compile(const VulkanCompileContext& ctx) {
    const PropertySet& p = properties();
    const int resolution = int(p.getInt(Msm::kResolution));
    mMaps.fits().setReceiverBackground(p.getBool(Msm::kReceiverBackground));
    mMaps.fits().setViewCull(p.getBool(Msm::kCull));
    // The border the filter's reads need: the blur's radius and the bilinear footprint's texel.
    mMaps.fits().fit(ctx.scene, resolution, int(p.getInt(Msm::kBlur)) / 2 + 1);
    VulkanMomentMaps::Settings s;
    // GL_RGBA16, GL_RGBA32F
    s.format = Msm::quantized(p) ? VK_FORMAT_R16G16B16A16_UNORM : VK_FORMAT_R32G32B32A32_SFLOAT;
    s.resolution = resolution;
    s.depthDefines = ctx.submitter.defines();
    Msm::addDefines(p, s.depthDefines);
    s.lightingFragment = "shadowmap/msm.frag";
    s.lightingDefines = ctx.defines();
    Msm::addDefines(p, s.lightingDefines);
    s.params = {float(p.getFloat(Msm::kMomentBias)), float(p.getFloat(Msm::kBleedReduction))};
    s.clear = Msm::noOccluder(p);
    s.blur = {.width = int(p.getInt(Msm::kBlur)), .logSpace = false};
    setPermutationKey(mMaps.compile(ctx, s));
}

void MsmVulkan::execute(VulkanFrameContext& ctx) {
    mCounters = mMaps.renderFrame(ctx);
}

} // namespace sb
