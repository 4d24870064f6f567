#pragma once
// `virtual`: virtual shadow maps with a page cache (Epic's UE5 documentation "Virtual Shadow Maps";
// Sakmary, Ryan, Hall, Lustri, "Virtual Shadow Maps", GPU Zen 3; NOTES-virtual.md holds the design). A
// directional light's map of virtual_resolution^2 texels in pages of page_size^2, only the pages a
// visible receiver reads backed by a slot of a physical pool (a 2D atlas) and drawn; with `cache` a page
// keeps its depth across frames until the light or a caster over it moves. The declaration (techniques/
// TechniqueInfo.h) its forms take. Not in the registry yet: the first slice (VirtualGL) is driven by
// its test alone.
#include "shading/Defines.h"
#include "techniques/PropertySet.h"
#include "techniques/TechniqueInfo.h"
#include "techniques/virtual/PageGeometry.h"

namespace sb {

struct Virtual {
    static constexpr const char* kVirtualResolution = "virtual_resolution";
    static constexpr const char* kPageSize = "page_size";
    static constexpr const char* kPoolPages = "pool_pages";
    static constexpr const char* kCache = "cache";

    static TechniqueInfo declaration();
    /// The sizes `p` asks for (refused by name when they do not tile: PageGeometry).
    static PageGeometry geometry(const PropertySet& p);
    /// How far around a receiver's texel its lookup reads, in texels: pcf x pcf nearest taps one texel
    /// apart reach (pcf - 1) / 2 each side, plus one for rounding. The marking rule's footprint.
    static float footprintTexels(const PropertySet& p);
    /// The sizes and the kernel as the shaders' defines (shaders/virtual/page_table.glsl).
    static void addPageDefines(const PropertySet& p, Defines& d);
};

} // namespace sb
