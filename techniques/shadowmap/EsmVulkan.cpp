#include "techniques/shadowmap/EsmVulkan.h"

namespace sb {

EsmVulkan::EsmVulkan() : VulkanTechnique(Esm::declaration()) {}

void EsmVulkan::setScene(const Scene& scene) {
    mMaps.fits().setScene(scene, properties());
}

void EsmVulkan::compile(const VulkanCompileContext& ctx) {
    const PropertySet& p = properties();
    const int resolution = int(p.getInt(Esm::kResolution));
    const float exponent = float(p.getFloat(Esm::kExponent));
    mMaps.fits().setReceiverBackground(p.getBool(Esm::kReceiverBackground));
    mMaps.fits().setViewCull(p.getBool(Esm::kCull));
    // The border the filter's reads need: the blur's radius and the bilinear footprint's texel.
    mMaps.fits().fit(ctx.scene, resolution, int(p.getInt(Esm::kBlur)) / 2 + 1);
    VulkanMomentMaps::Settings s;
    s.format = VK_FORMAT_R32_SFLOAT; // GL_R32F
    s.resolution = resolution;
    s.depthDefines = ctx.submitter.defines();
    s.lightingFragment = "shadowmap/esm.frag";
    s.lightingDefines = ctx.defines();
    s.params = {exponent, 0.0f};
    s.clear = {1.0f, 0.0f, 0.0f, 0.0f}; // d = 1: nothing in front of the far end
    s.blur = {.width = int(p.getInt(Esm::kBlur)), .logSpace = true, .exponent = exponent};
    setPermutationKey(mMaps.compile(ctx, s));
}

void EsmVulkan::execute(VulkanFrameContext& ctx) {
    mCounters = mMaps.renderFrame(ctx);
}

} // namespace sb
