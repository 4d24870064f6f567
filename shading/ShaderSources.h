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
    std::string compute;  ///< a compute program: this stage alone (vertex and fragment left "")
    /// A mesh pipeline (Vulkan, VK_EXT_mesh_shader): this stage instead of vertex (left "") and geometry.
    std::string mesh;

    /// The stages present, in pipeline order (vertex, geometry, fragment; mesh, fragment; or compute
    /// alone), each with its file.
    std::vector<std::pair<ShaderStage, const std::string*>> stages() const;
    /// "common-scene.vert+shadowmap-lighting.frag": the files in pipeline order, '/' as '-', joined by '+'.
    std::string programName() const;
    /// "vertex 'a.vert', fragment 'b.frag'": what a link error names.
    std::string describe() const;
};

} // namespace sb
