#pragma once
// `msm` on Vulkan: MsmGL's three passes ("depth", "blur", "lighting"; techniques/shadowmap/MsmGL.h has the
// method) with the same declaration, properties, light fits, culling and counters (MomentMapFits) and the
// same shaders, recorded into the frame's command buffer by VulkanMomentMaps: the four moments into an
// R16G16B16A16 unorm (quantised) or R32G32B32A32 float layer per light, the separable blur in linear mode,
// the Hamburger reconstruction in shadowmap/msm.frag. Point lights are refused as on GL.
#include "techniques/shadowmap/Msm.h"
#include "techniques/shadowmap/VulkanMomentMaps.h"
#include "techniques/vulkan/VulkanTechnique.h"

namespace sb {

class MsmVulkan final : public VulkanTechnique {
public:
    MsmVulkan();
    void setScene(const Scene& scene) override;
    /// As MsmGL: the light fits and the maps' fit to the receivers follow the scene.
    void sceneChanged(const Scene& scene, uint32_t) override { mMaps.sceneChanged(scene); }
    void compile(const VulkanCompileContext& ctx) override;
    void execute(VulkanFrameContext& ctx) override;
    Counters counters() const override { return mCounters; }
    const MapTexels* mapTexels() const override { return &mMaps.fits(); }

private:
    VulkanMomentMaps mMaps{"msm"};
    Counters mCounters;
};

} // namespace sb
