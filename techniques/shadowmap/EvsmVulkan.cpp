#include "techniques/shadowmap/EvsmVulkan.h"

namespace sb {

EvsmVulkan::EvsmVulkan() : VulkanTechnique(Evsm::declaration()) {}

void EvsmVulkan::setScene(const Scene& scene) {
    mMaps.fits().setScene(scene, properties());
}

void EvsmVulkan::compile(const VulkanCompileContext& ctx) {
    const PropertySet& p = properties();
    const int resolution = int(p.getInt(Evsm::kResolution));
    mMaps.fits().setReceiverBackground(p.getBool(Evsm::kReceiverBackground));
    mMaps.fits().setViewCull(p.getBool(Evsm::kCull));
    // The border the filter's reads need: the blur's radius and the bilinear footprint's texel.
    mMaps.fits().fit(ctx.scene, resolution, int(p.getInt(Evsm::kBlur)) / 2 + 1);
    VulkanMomentMaps::Settings s;
    // GL_RGBA32F, GL_RG32F
    s.format = Evsm::negativeWarp(p) ? VK_FORMAT_R32G32B32A32_SFLOAT : VK_FORMAT_R32G32_SFLOAT;
    s.resolution = resolution;
    s.depthDefines = ctx.submitter.defines();
    Evsm::addDefines(p, s.depthDefines);
    s.lightingFragment = "shadowmap/evsm.frag";
    s.lightingDefines = ctx.defines();
    Evsm::addDefines(p, s.lightingDefines);
    s.params = {float(p.getFloat(Evsm::kMinVariance)), float(p.getFloat(Evsm::kBleedReduction))};
    s.clear = Evsm::noOccluder(p);
    s.blur = {.width = int(p.getInt(Evsm::kBlur)), .logSpace = false};
    setPermutationKey(mMaps.compile(ctx, s));
}

void EvsmVulkan::execute(VulkanFrameContext& ctx) {
    mCounters = mMaps.renderFrame(ctx);
}

} // namespace sb
