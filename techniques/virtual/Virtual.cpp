#include "techniques/virtual/Virtual.h"

#include <string>

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
        integer(Virtual::kPoolPages, "1024", 1, 16384,
                "slots of the physical pool (pages that can hold depth at once)"),
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
    return {.name = "virtual",
            .description = "virtual shadow maps: a 16k map in pages, only the pages visible receivers read "
                           "drawn, kept across frames until something over them moves",
            .effects = Effect::HardShadows | Effect::SelfShadowing | Effect::NonPlanarReceivers,
            .capabilities = {{Api::GL, "GL 4.5", 4, 5, ""}},
            .passes = {"depth", "lighting"},
            .properties = declareProperties(),
            .quality = {P::pcfSweep(), P::biasConstantSweep(), P::biasSlopeSweep()},
            .resources = [](const PropertySet& p, const ResourceInputs& in) {
                const PageGeometry g = geometry(p);
                return squareMaps(g.atlasResolution(), kDepthTexelBytes, 1, in);
            }};
}

PageGeometry Virtual::geometry(const PropertySet& p) {
    return PageGeometry(int(p.getInt(kVirtualResolution)), int(p.getInt(kPageSize)),
                        int(p.getInt(kPoolPages)));
}

float Virtual::footprintTexels(const PropertySet& p) {
    return 0.5f * float(p.getInt(P::kPcf) - 1) + 1.0f;
}

void Virtual::addPageDefines(const PropertySet& p, Defines& d) {
    const PageGeometry g = geometry(p);
    d["VIRTUAL_RESOLUTION"] = std::to_string(g.virtualResolution());
    d["PAGE_SIZE"] = std::to_string(g.pageSize());
    d["ATLAS_PAGES"] = std::to_string(g.atlasPagesPerSide());
    d["FOOTPRINT"] = std::to_string(footprintTexels(p)); // "1.000000": a float literal
    d["PCF_SIZE"] = std::to_string(p.getInt(P::kPcf));
}

} // namespace sb
