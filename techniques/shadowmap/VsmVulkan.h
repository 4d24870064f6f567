#pragma once
// `vsm` on Vulkan: VsmGL's three passes ("depth", "blur", "lighting"; techniques/shadowmap/VsmGL.h has the
// method) with the same declaration, properties, light fits, culling and counters (MomentMapFits) and
// the same shaders, recorded into the frame's command buffer by VulkanMomentMaps: the moments (d, d^2) into
// an RG32F layer per light, the separable blur in linear mode, Chebyshev's bound in shadowmap/vsm.frag. Point
// lights are refused as on GL.
#include "techniques/shadowmap/Vsm.h"
#include "techniques/shadowmap/VulkanMomentMaps.h"
#include "techniques/vulkan/VulkanTechnique.h"

namespace sb {

class VsmVulkan final : public VulkanTechnique {
public:
    VsmVulkan();
    void setScene(const Scene& scene) override;
    /// As VsmGL: the light fits and the maps' fit to the receivers follow the scene.
    void sceneChanged(const Scene& scene, uint32_t) override { mMaps.sceneChanged(scene); }
    void compile(const VulkanCompileContext& ctx) override;
    void execute(VulkanFrameContext& ctx) override;
    Counters counters() const override { return mCounters; }
    const MapTexels* mapTexels() const override { return &mMaps.fits(); }

private:
    VulkanMomentMaps mMaps{"vsm"};
    Counters mCounters;
};

} // namespace sb
