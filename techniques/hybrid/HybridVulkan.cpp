#include "techniques/hybrid/HybridVulkan.h"

#include "core/Error.h"
#include "techniques/hybrid/HybridRouterScope.h"

namespace sb {

HybridVulkan::HybridVulkan(Factory create, std::vector<std::string> choices)
    : VulkanTechnique(Hybrid::declaration(choices)), mCreate(std::move(create)) {
    propertiesApplied();
}

HybridVulkan::~HybridVulkan() = default;

bool HybridVulkan::makeParts() {
    mParts.clear();
    mMissing.clear();
    for (const char* role : {Hybrid::kSelf, Hybrid::kCast}) {
        const std::string name = properties().getEnum(role);
        try {
            mParts.emplace_back(role, mCreate(name));
        } catch (const Error& e) {
            if (e.code() != ExitCode::Unsupported) throw;
            mParts.clear();
            mMissing = "hybrid: the " + std::string(role) + " part (" + name +
                       ") has no Vulkan form; name parts that have one, or run with --api gl";
            return false;
        }
    }
    deriveHybridInfo(mutableInfo(), mParts);
    return true;
}

void HybridVulkan::propertiesApplied() {
    // A part without a Vulkan form is refused when the hybrid is prepared (setScene), where every
    // caller expects a technique the device or API cannot run to say so (ExitCode::Unsupported).
    makeParts();
}

void HybridVulkan::setScene(const Scene& scene) {
    if (!mMissing.empty()) throw Error(mMissing, ExitCode::Unsupported);
    for (Part& part : mParts) part.setScene(scene);
}

void HybridVulkan::sceneChanged(const Scene& scene, uint32_t changes) {
    for (Part& part : mParts)
        if (part.scopeCount != 0) part.technique->sceneChanged(scene, changes);
}

void HybridVulkan::compile(const VulkanCompileContext& ctx) {
    for (Part& part : mParts)
        if (part.scopeCount != 0) part.technique->compile(ctx);
    setPermutationKey(hybridPermutationKey(mParts));
}

void HybridVulkan::runPart(Part& part, VulkanFrameContext& ctx) {
    part.submitter = &ctx.submitter;
    HybridRouterScope<VulkanPassTimer, VulkanSubmitter> scope(ctx.passes, ctx.submitter, &part);
    if (part.scopeCount == 0) {
        for (const std::string& pass : part.technique->info().passes) // renamed by the router
            ctx.passes.skip(pass.c_str(), Hybrid::emptyRoleReason(part.role));
        return;
    }
    part.technique->execute(ctx);
}

void HybridVulkan::execute(VulkanFrameContext& ctx) {
    // No state carries from one part to the next on Vulkan: each part binds its pipelines and sets in
    // its own render passes, which load what the other drew.
    for (Part& part : mParts) runPart(part, ctx);
    mCounters = hybridCounters(mParts);
}

} // namespace sb
