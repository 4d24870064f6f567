#include "techniques/virtual/Virtual.h"

#include <algorithm>
#include <string>

#include "techniques/ContactShadows.h"
#include "techniques/Property.h"
#include "techniques/ResourceEstimate.h"
#include "techniques/ShadowMapProperties.h"

namespace sb {

using P = ShadowMapProperties;

namespace {

/// The knobs, one maker call each (techniques/Property.h).
std::vector<PropertyDesc> declareProperties() {
    return {
        integer(Virtual::kVirtualResolution, "16384", 128, 16384,
                "width and height of the virtual map (texels): a multiple of page_size"),
        integer(Virtual::kPageSize, "128", 8, 1024, "width and height of a page (texels)"),
        integer(Virtual::kPoolPages, "1024", 1, 4096,
                "slots of the physical pool (pages that can hold depth at once): an atlas of "
                "ceil(sqrt(pool_pages))^2 pages, 64 KiB each at page_size 128"),
        integer(Virtual::kLevels, "0", 0, 15,
                "mip levels of the virtual map, each half the previous one's texels a side in pages of the "
                "same size; a receiver reads the level whose texels are nearest its pixel's footprint "
                "(0: every level, down to a single page)"),
        real(Virtual::kLodBias, "0", -8, 8,
             "added to log2 of level 0's texels per pixel before it picks the level (negative: sharper, "
             "more pages)"),
        choice(
            Virtual::kPath, "atomic", {"atomic", "sparse"},
            "atomic: pages in slots of an atlas, written with imageAtomicMin (both APIs); sparse: the "
            "virtual map one sparse-resident Vulkan image, its levels as mips, each page bound to its slot's "
            "memory (Vulkan, where the device has sparse residency: lavapipe 25.0.7; refused naming what it "
            "lacks)"),
        flag(Virtual::kCache, "true",
             "keep pages' depth across frames until the light or a caster over them moves"),
        P::biasConstant(
            "constant depth bias in steps of 2^-24, added in the page shader as glPolygonOffset's units"),
        P::biasSlope("slope-scaled depth bias, added in the page shader as glPolygonOffset's factor"),
        P::pcf("PCF kernel width: pcf x pcf nearest taps one texel apart, each through its page"),
    };
}

} // namespace

TechniqueInfo Virtual::declaration() {
    return ContactShadows::declare(
        {.name = "virtual",
         .description = "virtual shadow maps: a 16k map in 128^2 pages backed by a pool, only the pages "
                        "visible receivers read drawn (imageAtomicMin), at the mip level of their pixel, "
                        "kept across frames until the light or a caster over them moves (Epic Games, "
                        "Unreal Engine 5 documentation, Virtual Shadow Maps, the sections on pages and "
                        "caching; Sakmary et al., Virtual Shadow Maps, GPU Zen 3, ch. 12)",
         .effects = Effect::HardShadows | Effect::SelfShadowing | Effect::NonPlanarReceivers,
         .capabilities = {{Api::GL, "GL 4.5", 4, 5, ""}},
         .passes = {"depth", "lighting"},
         .properties = declareProperties(),
         .quality = {P::pcfSweep(), P::biasConstantSweep(), P::biasSlopeSweep()},
         .resources =
             [](const PropertySet& p, const ResourceInputs& in) {
                 const PageGeometry g = geometry(p);
                 return squareMaps(g.atlasResolution(), kDepthTexelBytes, 1, in);
             },
         .matrixVariants = {
             {std::string(kPath) + "=sparse", AccuracyRule::Map,
              "the atomic path's pages in a sparse-resident image instead of an atlas: the same "
              "page choice, depths and lookups (tests/VirtualVkTest.cpp holds its images to the "
              "atomic path's value for value), so it is held to the map rule as the atomic path",
              "GL has no sparse residency here: path=sparse is a Vulkan form (sparseBinding, "
              "sparseResidencyImage2D), judged on the driver that offers it"}}});
}

PageGeometry Virtual::geometry(const PropertySet& p) {
    const int resolution = int(p.getInt(kVirtualResolution));
    const int page = int(p.getInt(kPageSize));
    const int levels = int(p.getInt(kLevels));
    return PageGeometry(resolution, page, int(p.getInt(kPoolPages)),
                        levels == 0 ? std::max(1, PageGeometry::maxLevels(resolution, page)) : levels);
}

float Virtual::footprintTexels(const PropertySet& p) {
    return 0.5f * float(p.getInt(P::kPcf) - 1) + 1.0f;
}

Virtual::PageUniforms Virtual::pageUniforms(const PropertySet& p) {
    const PageGeometry g = geometry(p);
    return {glm::ivec4(g.virtualResolution(), g.pageSize(), g.atlasPagesPerSide(), g.levels()),
            glm::vec4(footprintTexels(p), float(p.getFloat(kLodBias)), float(p.getInt(P::kPcf)), 0.0f)};
}

} // namespace sb
