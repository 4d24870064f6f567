#pragma once
// Where a program is on PATH. ChildProcess starts children with execve, which takes a path, not a name,
// so the tools `bench bisect` runs (git, cmake, ninja, ccache) are looked up here first.
#include <string>

namespace sb {

class ToolPath {
public:
    /// The first executable `program` in a folder of PATH (/usr/bin:/bin when PATH is unset), or ""
    /// when there is none. A name with a '/' is returned as it is when executable.
    static std::string find(const std::string& program);
};

} // namespace sb
