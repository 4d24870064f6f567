#pragma once
// The files of one program (GL) or pipeline (Vulkan), relative to shaders/: the same sources on both
// APIs, the same dump layout (shading/ShaderDump.h).
#include <string>
#include <utility>
#include <vector>

#include "shading/ShaderStage.h"

namespace sb {

struct ShaderSources {
    std::string vertex;   ///< path relative to shaders/, e.g. "shadowmap/lighting.vert"
    std::string fragment; ///< may be "" for depth-only programs
    std::string geometry; ///< optional
    /// A compute program's one stage ("shadowmap/depth_range.comp"); set, it is the program's only stage
    /// and the others are left empty.
    std::string compute;

    /// The stages present, in pipeline order (vertex, geometry, fragment), each with its file; a compute
    /// program's compute stage alone.
    std::vector<std::pair<ShaderStage, const std::string*>> stages() const;
    /// "common-scene.vert+shadowmap-lighting.frag": the files in pipeline order, '/' as '-', joined by '+'.
    std::string programName() const;
    /// "vertex 'a.vert', fragment 'b.frag'": what a link error names.
    std::string describe() const;
};

} // namespace sb
