#include "registry/TechniqueRegistry.h"

#include "core/Error.h"
#include "core/Strings.h"
#include "core/Suggestion.h"
#include "reference/ReferenceGL.h"
#include "reference/ReferenceVulkan.h"
#include "techniques/blob/BlobGL.h"
#include "techniques/blob/BlobVulkan.h"
#include "techniques/hybrid/HybridGL.h"
#include "techniques/hybrid/HybridVulkan.h"
#include "techniques/none/NoneGL.h"
#include "techniques/none/NoneVulkan.h"
#include "techniques/occluder/OccluderGL.h"
#include "techniques/occluder/OccluderVulkan.h"
#include "techniques/planar/PlanarGL.h"
#include "techniques/planar/PlanarVulkan.h"
#include "techniques/projective/ProjectiveGL.h"
#include "techniques/projective/ProjectiveVulkan.h"
#include "techniques/proxy/ProxyGL.h"
#include "techniques/proxy/ProxyVulkan.h"
#include "techniques/raytraced/RayTraced.h"
#include "techniques/raytraced/RayTracedVulkan.h"
#include "techniques/shadowmap/CascadedGL.h"
#include "techniques/shadowmap/CascadedVulkan.h"
#include "techniques/shadowmap/CubeMapGL.h"
#include "techniques/shadowmap/CubeMapVulkan.h"
#include "techniques/shadowmap/Esm.h"
#include "techniques/shadowmap/Evsm.h"
#include "techniques/shadowmap/MomentMapGL.h"
#include "techniques/shadowmap/MomentMapVulkan.h"
#include "techniques/shadowmap/Msm.h"
#include "techniques/shadowmap/ParaboloidGL.h"
#include "techniques/shadowmap/ParaboloidVulkan.h"
#include "techniques/shadowmap/PcssGL.h"
#include "techniques/shadowmap/PcssVulkan.h"
#include "techniques/shadowmap/ShadowMapGL.h"
#include "techniques/shadowmap/ShadowMapVulkan.h"
#include "techniques/shadowmap/Vsm.h"
#include "techniques/synthetic/SyntheticGL.h"
#include "techniques/synthetic/SyntheticVulkan.h"
#include "techniques/virtual/VirtualGL.h"
#include "techniques/virtual/VirtualVulkan.h"
#include "techniques/volume/VolumeGL.h"
#include "techniques/volume/VolumeVulkan.h"

namespace sb {

namespace {

/// What a hybrid's role may name: every shadow technique, not the judge, the workloads or itself, and
/// only one with a form on both APIs: the hybrid's declaration, its roles' choices included, is the same
/// on both.
bool isHybridPart(const std::string& name) {
    return name != "hybrid" && name != "reference" && name != "synthetic" &&
           TechniqueRegistry::has(name, Api::GL) && TechniqueRegistry::has(name, Api::Vulkan);
}

std::vector<std::string> partNames() {
    std::vector<std::string> out;
    for (const std::string& name : TechniqueRegistry::names())
        if (isHybridPart(name)) out.push_back(name);
    return out;
}

std::unique_ptr<GlTechnique> createPart(const std::string& name) {
    return TechniqueRegistry::create(name);
}

/// A hybrid part's Vulkan form at its default properties (Unsupported for a technique without one).
std::unique_ptr<VulkanTechnique> createVulkanPart(const std::string& name) {
    return TechniqueRegistry::createVulkan(TechniqueSpec{name, {}});
}

} // namespace

template <typename T>
std::unique_ptr<GlTechnique> gl() {
    return std::make_unique<T>();
}
template <typename T>
std::unique_ptr<VulkanTechnique> vulkan() {
    return std::make_unique<T>();
}
/// A filterable shadow map's forms: one GL and one Vulkan class over the member's kind.
template <MomentMapKind (*Kind)()>
std::unique_ptr<GlTechnique> momentsGl() {
    return std::make_unique<MomentMapGL>(Kind());
}
template <MomentMapKind (*Kind)()>
std::unique_ptr<VulkanTechnique> momentsVulkan() {
    return std::make_unique<MomentMapVulkan>(Kind());
}

const std::vector<TechniqueRegistry::Entry>& TechniqueRegistry::entries() {
    // The one table of techniques. Order is the order of --list and of "all".
    static const std::vector<Entry> kEntries = {
        {"none", gl<NoneGL>, vulkan<NoneVulkan>},
        {"shadowmap", gl<ShadowMapGL>, vulkan<ShadowMapVulkan>},
        // The shadow-map family: omni maps for point lights, cascades, soft and filterable maps.
        {"cubemap", gl<CubeMapGL>, vulkan<CubeMapVulkan>},
        {"paraboloid", gl<ParaboloidGL>, vulkan<ParaboloidVulkan>},
        {"cascaded", gl<CascadedGL>, vulkan<CascadedVulkan>},
        {"pcss", gl<PcssGL>, vulkan<PcssVulkan>},
        {"vsm", momentsGl<&Vsm::kind>, momentsVulkan<&Vsm::kind>},
        {"esm", momentsGl<&Esm::kind>, momentsVulkan<&Esm::kind>},
        {"evsm", momentsGl<&Evsm::kind>, momentsVulkan<&Evsm::kind>},
        {"msm", momentsGl<&Msm::kind>, momentsVulkan<&Msm::kind>},
        // A 16k^2 map in pages, only the needed ones drawn and cached across frames.
        {"virtual", gl<VirtualGL>, vulkan<VirtualVulkan>},
        {"volume", gl<VolumeGL>, vulkan<VolumeVulkan>},
        {"occluder", gl<OccluderGL>, vulkan<OccluderVulkan>},
        {"proxy", gl<ProxyGL>, vulkan<ProxyVulkan>},
        {"planar", gl<PlanarGL>, vulkan<PlanarVulkan>},
        {"projective", gl<ProjectiveGL>, vulkan<ProjectiveVulkan>},
        {"blob", gl<BlobGL>, vulkan<BlobVulkan>},
        // Two of the above in one frame, one per role (Coleman's conclusion): the registry makes its parts.
        {"hybrid", [] { return std::unique_ptr<GlTechnique>(new HybridGL(createPart, partNames())); },
         [] { return std::unique_ptr<VulkanTechnique>(new HybridVulkan(createVulkanPart, partNames())); }},
        // Ray queries are Vulkan's: no GL form.
        {"raytraced", nullptr, vulkan<RayTracedVulkan>, RayTraced::kGlRefusal},
        {"reference", gl<ReferenceGL>, vulkan<ReferenceVulkan>},
        // Not a shadow technique: the bottleneck study's calibration workloads.
        {"synthetic", gl<SyntheticGL>, vulkan<SyntheticVulkan>},
    };
    return kEntries;
}

std::vector<std::string> TechniqueRegistry::names() {
    std::vector<std::string> out;
    for (const Entry& e : entries()) out.emplace_back(e.name);
    return out;
}

bool TechniqueRegistry::has(const std::string& name, Api api) {
    for (const Entry& e : entries())
        if (name == e.name) return api == Api::GL ? bool(e.gl) : bool(e.vulkan);
    return false;
}

std::vector<std::string> TechniqueRegistry::namesOn(Api api) {
    std::vector<std::string> out;
    for (const Entry& e : entries())
        if (has(e.name, api)) out.emplace_back(e.name);
    return out;
}

namespace {

const TechniqueRegistry::Entry& entryOf(const std::string& name) {
    for (const TechniqueRegistry::Entry& e : TechniqueRegistry::entries())
        if (name == e.name) return e;
    const std::string known = join(TechniqueRegistry::names(), ", ");
    // `-t auto` is resolved to a technique by `bench` runs (bench/lib/select) before anything is created;
    // a command that reaches here with it (sweep, bottleneck, explain) does not make that choice.
    if (name == "auto")
        throw Error("-t auto is taken by `bench` and `bench accuracy` runs only; this command needs a "
                    "named technique (known: " +
                    known + ")");
    throw Error("unknown technique '" + name + "'" +
                Suggestion::didYouMean(name, TechniqueRegistry::names()) + " (known: " + known + ")");
}

void apply(Technique& t, const TechniqueSpec& spec) {
    t.properties().apply(spec.properties);
    t.propertiesApplied();
}

} // namespace

std::unique_ptr<Technique> TechniqueRegistry::create(const TechniqueSpec& spec, Api api) {
    if (api == Api::Vulkan) return createVulkan(spec);
    return create(spec);
}

std::unique_ptr<GlTechnique> TechniqueRegistry::create(const std::string& name) {
    const Entry& e = entryOf(name);
    if (!e.gl)
        throw Error(e.glRefusal ? std::string(e.glRefusal)
                                : name + " has no GL form; run it with --api vulkan",
                    ExitCode::Unsupported);
    return e.gl();
}

std::unique_ptr<Technique> TechniqueRegistry::describe(const TechniqueSpec& spec) {
    const Entry& e = entryOf(spec.name);
    std::unique_ptr<Technique> t;
    if (e.gl)
        t = e.gl();
    else
        t = e.vulkan();
    apply(*t, spec);
    return t;
}

std::unique_ptr<GlTechnique> TechniqueRegistry::create(const TechniqueSpec& spec) {
    auto t = create(spec.name);
    apply(*t, spec);
    return t;
}

std::unique_ptr<VulkanTechnique> TechniqueRegistry::createVulkan(const TechniqueSpec& spec) {
    const Entry& e = entryOf(spec.name);
    if (!e.vulkan)
        throw Error(spec.name + " has no Vulkan form yet (on Vulkan: " + join(namesOn(Api::Vulkan), ", ") +
                        "); run it with --api gl",
                    ExitCode::Unsupported);
    auto t = e.vulkan();
    apply(*t, spec);
    return t;
}

} // namespace sb
