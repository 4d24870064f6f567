#pragma once
// `esm` on Vulkan: EsmGL's three passes ("depth", "blur", "lighting"; techniques/shadowmap/EsmGL.h has the
// method) with the same declaration, properties, light fits, culling and counters (MomentMapFits) and
// the same shaders, recorded into the frame's command buffer by VulkanMomentMaps: the linear depth into an
// R32F layer per light, the separable blur in log space (exp(c d)), the exponential test in
// shadowmap/esm.frag. Point lights are refused as on GL.
#include "techniques/shadowmap/Esm.h"
#include "techniques/shadowmap/VulkanMomentMaps.h"
#include "techniques/vulkan/VulkanTechnique.h"

namespace sb {

class EsmVulkan final : public VulkanTechnique {
public:
    EsmVulkan();
    void setScene(const Scene& scene) override;
    /// As EsmGL: the light fits and the maps' fit to the receivers follow the scene.
    void sceneChanged(const Scene& scene, uint32_t) override { mMaps.sceneChanged(scene); }
    void compile(const VulkanCompileContext& ctx) override;
    void execute(VulkanFrameContext& ctx) override;
    Counters counters() const override { return mCounters; }
    const MapTexels* mapTexels() const override { return &mMaps.fits(); }

private:
    VulkanMomentMaps mMaps{"esm"};
    Counters mCounters;
};

} // namespace sb
