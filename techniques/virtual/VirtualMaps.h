#pragma once
// What `virtual`'s GL and Vulkan forms share (NOTES-virtual.md, "Passes"), as CascadedMaps is for
// `cascaded`'s: which light has a map (one directional or spot light that casts shadows; a point light
// or a second shadowed light refused by name), its transform (a directional light's fitted once to the
// whole scene, LightFitBounds::Scene; a spot light's its cone, scenes/LightFit.h), refitted only when
// the light moves, so that moving casters and a moving camera leave it, and the cache, alone), the page
// cache, the casters' footprints for invalidation, the CPU allocation from the GPU's marks, the runs of
// pages the depth pass draws and the frame's counters. The forms only record: they draw what this
// class hands them.
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/Scene.h"
#include "techniques/PropertySet.h"
#include "techniques/Submission.h"
#include "techniques/TechniqueInfo.h"
#include "techniques/virtual/CasterFootprints.h"
#include "techniques/virtual/VirtualMapTexels.h"
#include "techniques/virtual/VirtualPageCache.h"

namespace sb {

/// Pages of one row of one level with consecutive numbers: what the depth pass draws under one scissor.
struct PageRun {
    int level = 0;
    glm::ivec2 first{0}; ///< the run's first page, in its level's page coordinates
    int count = 0;
    /// The clip-space crop that takes the run's pages to [-1, 1]^2 (never drawn with: the pages are
    /// drawn in the whole level's coordinates); times the light's viewProj, what its casters are
    /// culled against.
    glm::mat4 crop(const PageGeometry& g) const;
};

class VirtualMaps {
public:
    /// Picks the mapped light of `scene` (throws sb::Error(Unsupported) naming a point light that casts
    /// shadows, or a second shadowed light), makes the cache of `p`'s sizes and fits.
    void setScene(const Scene& scene, const PropertySet& p);
    /// A moved light refits the map (the next frame drops every page); moved casters queue their old
    /// and new pages for the next frame's invalidation.
    void sceneChanged(const Scene& scene, uint32_t changes);

    /// The light with a map, or -1 where none casts shadows.
    int light() const { return mLight; }
    const glm::mat4& lightViewProj() const { return mLightViewProj; }
    const PageGeometry& geometry() const { return mCache->geometry(); }

    /// A frame's allocation from the marks the GPU read back: `requests` holds a word per page
    /// (PageGeometry's numbering; non-zero: needed), at least pageCount() of them. Runs the cache's frame
    /// (cache `on` or off), fills `table` with the GPU's table words (tableRows() x pagesPerSide(), the
    /// tail zero) and returns the runs to draw.
    const std::vector<PageRun>& allocate(const uint32_t* requests, bool on, std::vector<uint32_t>& table);
    /// The last allocate()'s runs.
    const std::vector<PageRun>& runs() const { return mRuns; }
    /// The pages allocate() returned are drawn: their content is valid.
    void rendered() { mCache->rendered(); }
    const VirtualPageCache& cache() const { return *mCache; }
    const PageCounts& counts() const { return mCache->counts(); }

    /// The frame's counters: DepthLightingFrame's (shadow_map_texels the texels of the pages drawn),
    /// then PageCounts'.
    Counters counters(const SubmitStats& s) const;
    /// Where the lighting pass looks points up (camera set by the form each frame).
    VirtualMapTexels& texels() { return mTexels; }
    const VirtualMapTexels& texels() const { return mTexels; }

private:
    void fitLight(const Scene& scene);

    std::optional<VirtualPageCache> mCache;
    CasterFootprints mCasters;
    std::vector<PageRect> mMoved; ///< pages moved casters covered, for the next frame's invalidation
    int mLight = -1;
    glm::mat4 mLightViewProj{1.0f};
    float mLodBias = 0.0f;
    std::vector<uint8_t> mNeeded;
    std::vector<PageRun> mRuns;
    VirtualMapTexels mTexels;
};

} // namespace sb
