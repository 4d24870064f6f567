#pragma once
// A bicubic Bezier patch and the reader for the .bpt patch-file format of the Utah teapot data:
//   line 1: number of patches
//   per patch: a line "3 3" (u and v degree), then 16 control points "x y z", row-major (u major).
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace sb {

class BezierPatch {
public:
    glm::vec3 control[4][4]{}; ///< control[i][j]: i along u, j along v

    glm::vec3 evaluate(float u, float v) const;
    glm::vec3 derivativeU(float u, float v) const;
    glm::vec3 derivativeV(float u, float v) const;

    /// Reads every patch of a .bpt file; throws sb::Error "patch file '<path>': <reason>" naming the
    /// line for malformed content (only bicubic "3 3" patches are supported).
    static std::vector<BezierPatch> readBptFile(const std::string& path);
    /// The same for text already in memory (`sourceName` is used in error messages).
    static std::vector<BezierPatch> parseBpt(const std::string& text, const std::string& sourceName);
};

} // namespace sb
