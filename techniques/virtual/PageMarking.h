#pragma once
// `virtual`'s marking rule (NOTES-virtual.md, "Passes", step 2): which pages of the virtual map a
// receiver's shadow lookup reads. The GPU marks from the view's depth in a compute pass, one invocation
// per pixel; this class states the same rule on the CPU, for the unit tests and for anyone reading it:
// a world point p seen by the camera projects into the light's map at texel t = (clip.xy / clip.w * 0.5
// + 0.5) * virtualResolution, and the lookup reads texels within `footprintTexels` of t (the filter's
// half-width, the normal offset and one for rounding), so every page that square [t - f, t + f] touches
// is needed, the neighbours across a page seam included. A point whose square lies wholly outside the
// map needs nothing (the lookup says lit there), and so does one behind a perspective light (w <= 0).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "techniques/virtual/PageGeometry.h"

namespace sb {

class PageMarking {
public:
    PageMarking(const PageGeometry& geometry, float footprintTexels);

    /// The pages of level `level` world point `p`'s lookup reads in the map of `lightViewProj` (world ->
    /// map clip, GL conventions): its texel there is level 0's divided by 2^level, the footprint in
    /// that level's texels.
    PageRect pagesOf(const glm::mat4& lightViewProj, const glm::vec3& p, int level = 0) const;
    /// Marks pagesOf(p, level) in `needed` (a byte per page, PageGeometry's numbering).
    void mark(const glm::mat4& lightViewProj, const glm::vec3& p, std::vector<uint8_t>& needed,
              int level = 0) const;

private:
    PageGeometry mGeometry;
    float mFootprint;
};

} // namespace sb
