#include "techniques/TechniqueRegistry.h"
#include "core/Strings.h"

#include "core/Error.h"
#include "reference/ReferenceTechnique.h"
#include "techniques/blob/BlobTechnique.h"
#include "techniques/hybrid/HybridTechnique.h"
#include "techniques/none/NoneTechnique.h"
#include "techniques/none/NoneVulkan.h"
#include "techniques/occluder/OccluderTechnique.h"
#include "techniques/planar/PlanarTechnique.h"
#include "techniques/projective/ProjectiveTechnique.h"
#include "techniques/proxy/ProxyTechnique.h"
#include "techniques/shadowmap/CascadedTechnique.h"
#include "techniques/shadowmap/CubeMapTechnique.h"
#include "techniques/shadowmap/CubeMapVulkan.h"
#include "techniques/shadowmap/EsmTechnique.h"
#include "techniques/shadowmap/ParaboloidTechnique.h"
#include "techniques/shadowmap/PcssTechnique.h"
#include "techniques/shadowmap/ShadowMapTechnique.h"
#include "techniques/shadowmap/ShadowMapVulkan.h"
#include "techniques/shadowmap/VsmTechnique.h"
#include "techniques/synthetic/SyntheticTechnique.h"
#include "techniques/volume/VolumeTechnique.h"
#include "techniques/volume/VolumeVulkan.h"

namespace sb {

namespace {

/// What a hybrid's role may name: every shadow technique, not the judge, the workloads or itself.
bool isHybridPart(const std::string& name) {
    return name != "hybrid" && name != "reference" && name != "synthetic";
}

std::vector<std::string> partNames() {
    std::vector<std::string> out;
    for (const std::string& name : TechniqueRegistry::names())
        if (isHybridPart(name)) out.push_back(name);
    return out;
}

std::unique_ptr<Technique> createPart(const std::string& name) {
    return TechniqueRegistry::create(name);
}

} // namespace

const std::vector<TechniqueRegistry::Entry>& TechniqueRegistry::entries() {
    // The one table of techniques. Order is the order of --list and of "all".
    static const std::vector<Entry> kEntries = {
        {"none", [] { return std::unique_ptr<Technique>(new NoneTechnique()); }},
        {"shadowmap", [] { return std::unique_ptr<Technique>(new ShadowMapTechnique()); }},
        // The shadow-map family: omni maps for point lights, cascades, soft and filterable maps.
        {"cubemap", [] { return std::unique_ptr<Technique>(new CubeMapTechnique()); }},
        {"paraboloid", [] { return std::unique_ptr<Technique>(new ParaboloidTechnique()); }},
        {"cascaded", [] { return std::unique_ptr<Technique>(new CascadedTechnique()); }},
        {"pcss", [] { return std::unique_ptr<Technique>(new PcssTechnique()); }},
        {"vsm", [] { return std::unique_ptr<Technique>(new VsmTechnique()); }},
        {"esm", [] { return std::unique_ptr<Technique>(new EsmTechnique()); }},
        {"volume", [] { return std::unique_ptr<Technique>(new VolumeTechnique()); }},
        {"occluder", [] { return std::unique_ptr<Technique>(new OccluderTechnique()); }},
        {"proxy", [] { return std::unique_ptr<Technique>(new ProxyTechnique()); }},
        {"planar", [] { return std::unique_ptr<Technique>(new PlanarTechnique()); }},
        {"projective", [] { return std::unique_ptr<Technique>(new ProjectiveTechnique()); }},
        {"blob", [] { return std::unique_ptr<Technique>(new BlobTechnique()); }},
        // Two of the above in one frame, one per role (Coleman's conclusion): the registry makes its parts.
        {"hybrid", [] { return std::unique_ptr<Technique>(new HybridTechnique(createPart, partNames())); }},
        {"reference", [] { return std::unique_ptr<Technique>(new ReferenceTechnique()); }},
        // Not a shadow technique: the bottleneck study's calibration workloads.
        {"synthetic", [] { return std::unique_ptr<Technique>(new SyntheticTechnique()); }},
    };
    return kEntries;
}

std::vector<std::string> TechniqueRegistry::names() {
    std::vector<std::string> out;
    for (const Entry& e : entries()) out.emplace_back(e.name);
    return out;
}

std::unique_ptr<Technique> TechniqueRegistry::create(const std::string& name) {
    for (const Entry& e : entries())
        if (name == e.name) return e.create();
    std::string known = join(names(), ", ");
    // `-t auto` is resolved to a technique by `bench` runs (bench/select) before anything is created;
    // a command that reaches here with it (sweep, bottleneck, explain) does not make that choice.
    if (name == "auto")
        throw Error("-t auto is taken by `bench` and `bench accuracy` runs only; this command needs a "
                    "named technique (known: " +
                    known + ")");
    throw Error("unknown technique '" + name + "' (known: " + known + ")");
}

std::unique_ptr<Technique> TechniqueRegistry::create(const TechniqueSpec& spec) {
    auto t = create(spec.name);
    t->properties().apply(spec.properties);
    t->propertiesApplied();
    return t;
}

const std::vector<TechniqueRegistry::VulkanEntry>& TechniqueRegistry::vulkanEntries() {
    // The techniques with a Vulkan form (techniques/vulkan/VulkanTechnique.h); the others run on GL only
    // and --api vulkan refuses them (exit 3), as --list says.
    static const std::vector<VulkanEntry> kEntries = {
        {"none", [] { return std::unique_ptr<VulkanTechnique>(new NoneVulkan()); }},
        {"cubemap", [] { return std::unique_ptr<VulkanTechnique>(new CubeMapVulkan()); }},
        {"shadowmap", [] { return std::unique_ptr<VulkanTechnique>(new ShadowMapVulkan()); }},
        {"volume", [] { return std::unique_ptr<VulkanTechnique>(new VolumeVulkan()); }},
    };
    return kEntries;
}

bool TechniqueRegistry::hasVulkan(const std::string& name) {
    for (const VulkanEntry& e : vulkanEntries())
        if (name == e.name) return true;
    return false;
}

std::unique_ptr<VulkanTechnique> TechniqueRegistry::createVulkan(const TechniqueSpec& spec) {
    for (const VulkanEntry& e : vulkanEntries()) {
        if (spec.name != e.name) continue;
        auto t = e.create();
        t->properties().apply(spec.properties);
        return t;
    }
    create(spec.name); // an unknown name: the same error as on GL
    std::vector<std::string> known;
    for (const VulkanEntry& e : vulkanEntries()) known.emplace_back(e.name);
    throw Error(spec.name + " has no Vulkan form yet (on Vulkan: " + join(known, ", ") +
                    "); run it with --api gl",
                ExitCode::Unsupported);
}

} // namespace sb
