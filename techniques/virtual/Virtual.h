#pragma once
// `virtual`: virtual shadow maps with a page cache (Epic's UE5 documentation "Virtual Shadow Maps";
// Sakmary, Ryan, Hall, Lustri, "Virtual Shadow Maps", GPU Zen 3; NOTES-virtual.md holds the design). A
// directional or spot light's map of virtual_resolution^2 texels in pages of page_size^2, only the pages a
// visible receiver reads backed by a slot of a physical pool (a 2D atlas) and drawn; with `cache` a page
// keeps its depth across frames until the light or a caster over it moves. The declaration (techniques/
// TechniqueInfo.h) its forms take: VirtualGL and VirtualVulkan (the atomic path), registered as
// `virtual`.
#include <glm/glm.hpp>

#include "techniques/PropertySet.h"
#include "techniques/TechniqueInfo.h"
#include "techniques/virtual/PageGeometry.h"

namespace sb {

struct Virtual {
    static constexpr const char* kVirtualResolution = "virtual_resolution";
    static constexpr const char* kPageSize = "page_size";
    static constexpr const char* kPoolPages = "pool_pages";
    static constexpr const char* kCache = "cache";
    static constexpr const char* kLevels = "levels";
    static constexpr const char* kLodBias = "lod_bias";
    static constexpr const char* kPath = "path";

    static TechniqueInfo declaration();
    /// The sizes `p` asks for (refused by name when they do not tile: PageGeometry); `levels` 0 is every
    /// level PageGeometry::maxLevels allows.
    static PageGeometry geometry(const PropertySet& p);
    /// How far around a receiver's texel its lookup reads, in texels: pcf x pcf nearest taps one texel
    /// apart reach (pcf - 1) / 2 each side, plus one for rounding. The marking rule's footprint.
    static float footprintTexels(const PropertySet& p);
    /// shaders/virtual/page_table.glsl's uniforms: geometry = (virtual resolution, page size, atlas pages
    /// a side, levels), lod = (footprintTexels, lod_bias, pcf, 0). Uniforms, not defines: no size or
    /// kernel costs a program (the permutation test's axes stay the scene's).
    struct PageUniforms {
        glm::ivec4 geometry{0};
        glm::vec4 lod{0.0f};
    };
    static PageUniforms pageUniforms(const PropertySet& p);
    /// Whether `p` asks for the sparse-residency path (path=sparse: Vulkan's; NOTES-virtual.md).
    static bool sparse(const PropertySet& p) { return p.getEnum(kPath) == "sparse"; }
};

} // namespace sb
