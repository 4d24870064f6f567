#pragma once
// `hybrid` on Vulkan (techniques/vulkan/VulkanTechnique.h): HybridGL's two parts in one frame, each the
// Vulkan form of the technique its role names, recorded into the frame's command buffer one after the
// other. The same declaration, passes ("self_lighting", "cast_depth" ...), view scopes and counters as
// HybridGL (techniques/hybrid/HybridPart.h holds what both forms share). Every part render pass loads
// the targets (VulkanTargets::beginPass), so the cast part's receivers are depth-tested against the
// casters the self part drew, as on GL.
//
// A role may name any technique that has a Vulkan form; one that has none is refused with
// ExitCode::Unsupported naming the role and the technique.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "techniques/hybrid/Hybrid.h"
#include "techniques/hybrid/HybridPart.h"
#include "techniques/vulkan/VulkanTechnique.h"

namespace sb {

class HybridVulkan final : public VulkanTechnique {
public:
    /// Makes a part's Vulkan form by registry name (throws sb::Error, ExitCode::Unsupported for a
    /// technique without one).
    using Factory = std::function<std::unique_ptr<VulkanTechnique>(const std::string& name)>;
    /// `choices`: the registry names a role may take, in --list order (the same as on GL).
    HybridVulkan(Factory create, std::vector<std::string> choices);
    ~HybridVulkan() override;

    /// Creates the parts the `self` and `cast` properties name, and derives this technique's effects,
    /// capabilities and passes from them. A part without a Vulkan form leaves the hybrid without parts,
    /// refused by setScene.
    void propertiesApplied() override;
    /// Throws sb::Error(Unsupported) naming the role whose technique has no Vulkan form.
    void setScene(const Scene& scene) override;
    /// Each prepared part follows the scene as it would alone.
    void sceneChanged(const Scene& scene, uint32_t changes) override;
    void compile(const VulkanCompileContext& ctx) override;
    void execute(VulkanFrameContext& ctx) override;
    Counters counters() const override { return mCounters; }
    /// Each instance's role's technique's (HybridMapTexels).
    const MapTexels* mapTexels() const override { return &mMapTexels; }

private:
    using Part = HybridPart<VulkanTechnique, VulkanSubmitter>;
    /// Makes both parts; false (and mMissing says why) when a role's technique has no Vulkan form.
    bool makeParts();
    void runPart(Part& part, VulkanFrameContext& ctx);

    Factory mCreate;
    std::vector<Part> mParts; ///< self, then cast
    HybridMapTexels<Part> mMapTexels{mParts};
    std::string mMissing; ///< why the parts could not be made ("" when they are)
    Counters mCounters;
};

} // namespace sb
