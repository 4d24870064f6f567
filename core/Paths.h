#pragma once
// Where run-time files (shaders/, scenes/data/) are found: next to the running binary first (the
// build copies them there), then in the source tree compiled in as SHADOWBENCH_SOURCE_DIR.
#include <string>
#include <vector>

namespace sb {

struct Paths {
    /// Directories searched, in order, for a relative resource path such as "shaders/common/x.glsl".
    static std::vector<std::string> searchRoots();
    /// The first existing file for `relative`, or "" if none.
    static std::string findResource(const std::string& relative);
    /// Reads a whole file; throws sb::Error "cannot read '<path>': <strerror>".
    static std::string readTextFile(const std::string& path);
};

} // namespace sb
