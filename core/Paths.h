#pragma once
// Where run-time files (shaders/, scenes/data/, tools/) are found: next to the running binary first (the
// build copies them there), then in an installed prefix (<exe>/../share/shadowbench, where
// `cmake --install` puts them), then in the source tree compiled in as SHADOWBENCH_SOURCE_DIR.
#include <string>
#include <vector>

namespace sb {

struct Paths {
    /// Directories searched, in order, for a relative resource path such as "shaders/common/x.glsl".
    static std::vector<std::string> searchRoots();
    /// The first existing file for `relative`, or "" if none.
    static std::string findResource(const std::string& relative);
    /// The first existing directory for `relative` (e.g. "shaders"); throws sb::Error naming the
    /// roots searched when there is none.
    static std::string findResourceDirectory(const std::string& relative);
    /// Reads a whole file; throws sb::Error "cannot read '<path>': <strerror>".
    static std::string readTextFile(const std::string& path);
};

} // namespace sb
