#pragma once
// The Vulkan form of every filterable shadow map (`vsm`, `esm`, `evsm`, `msm`): MomentMapGL's three
// passes ("depth", "blur", "lighting") with the same declaration, kind (techniques/shadowmap/
// MomentMapKind.h), light fits, culling and counters (MomentMapFits) and the same shaders, recorded into
// the frame's command buffer by VulkanMomentMaps. Point lights are refused as on GL.
#include "techniques/shadowmap/MomentMapKind.h"
#include "techniques/shadowmap/VulkanMomentMaps.h"
#include "techniques/vulkan/VulkanTechnique.h"

namespace sb {

class MomentMapVulkan final : public VulkanTechnique {
public:
    explicit MomentMapVulkan(const MomentMapKind& kind);
    void setScene(const Scene& scene) override;
    void propertiesApplied() override; ///< contact=on's pass "view_depth"
    /// The light fits and the blocks follow the scene (VulkanMomentMaps::sceneChanged).
    void sceneChanged(const Scene& scene, uint32_t) override { mMaps.sceneChanged(scene); }
    void compile(const VulkanCompileContext& ctx) override;
    void execute(VulkanFrameContext& ctx) override;
    Counters counters() const override { return mCounters; }
    const MapTexels* mapTexels() const override { return &mMaps.fits(); }

private:
    MomentMapKind mKind;
    VulkanMomentMaps mMaps;
    Counters mCounters;
};

} // namespace sb
