#pragma once
// `evsm` on Vulkan: EvsmGL's three passes ("depth", "blur", "lighting"; techniques/shadowmap/EvsmGL.h has the
// method) with the same declaration, properties, light fits, culling and counters (MomentMapFits) and the
// same shaders, recorded into the frame's command buffer by VulkanMomentMaps: the warped moments into an
// RG32F (components=2) or RGBA32F (components=4) layer per light, the separable blur in linear mode, the
// bounds in shadowmap/evsm.frag. Point lights are refused as on GL.
#include "techniques/shadowmap/Evsm.h"
#include "techniques/shadowmap/VulkanMomentMaps.h"
#include "techniques/vulkan/VulkanTechnique.h"

namespace sb {

class EvsmVulkan final : public VulkanTechnique {
public:
    EvsmVulkan();
    void setScene(const Scene& scene) override;
    /// As EvsmGL: the light fits and the maps' fit to the receivers follow the scene.
    void sceneChanged(const Scene& scene, uint32_t) override { mMaps.sceneChanged(scene); }
    void compile(const VulkanCompileContext& ctx) override;
    void execute(VulkanFrameContext& ctx) override;
    Counters counters() const override { return mCounters; }
    const MapTexels* mapTexels() const override { return &mMaps.fits(); }

private:
    VulkanMomentMaps mMaps{"evsm"};
    Counters mCounters;
};

} // namespace sb
