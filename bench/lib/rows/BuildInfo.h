#pragma once
// What this binary is: its version, the commit it was built from and how it was built. The definitions
// are generated on every build by cmake/BuildStamp.cmake, so the commit is the source tree's state when
// the binary was compiled, never the tree's state when it runs (a tree edited or checked out after the
// build does not change what the binary reports). `bench --version` prints these, and every result row
// records commit() as git_commit.
namespace sb {

struct BuildInfo {
    /// The project's version (CMakeLists.txt `project(... VERSION ...)`).
    static const char* version();
    /// `git describe --always --dirty --abbrev=12` of the source tree at build time ("unknown" outside
    /// a git checkout, e.g. a source tarball); "-dirty" marks a build of uncommitted changes.
    static const char* commit();
    /// CMAKE_BUILD_TYPE (Release, Debug, RelWithDebInfo ...).
    static const char* buildType();
    /// The C++ compiler's id and version, e.g. "GNU 12.2.0".
    static const char* compiler();
};

} // namespace sb
