#pragma once
// Where `bench bisect` builds its commits: ONE git worktree (`src/`) and ONE build folder (`build/`)
// under a cache folder outside the source tree (default $XDG_CACHE_HOME/shadowbench/bisect/<repo>, else
// /var/tmp/shadowbench-bisect-<user>/<repo>). Each commit is checked out into the same worktree, so
// git rewrites only the files that differ and ninja recompiles only those (and the build stamp) in the
// same build folder; ccache is the compiler launcher when it is on PATH.
//
// The worktree is registered on construction and unregistered (its files removed) by the destructor,
// so an error or an interrupt that unwinds leaves no registration in the repository; the build folder
// stays for the next bisection (clean() removes it and the cache folder).
#include <string>

#include "bench/lib/bisect/GitRepo.h"

namespace sb {

class BisectWorkspace {
public:
    /// The cache folder of `repo` under `cacheRoot` ("" for the default above). Error(BadInput) when
    /// it lies inside the repository's source tree.
    static std::string folderFor(const GitRepo& repo, const std::string& cacheRoot);
    /// Throws Error(Unsupported) when cmake or ninja does not run.
    static void requireBuildTools();

    /// Registers the worktree at `folder`/src, checked out at `commit`.
    BisectWorkspace(const GitRepo& repo, std::string folder, const std::string& commit);
    ~BisectWorkspace();
    BisectWorkspace(const BisectWorkspace&) = delete;
    BisectWorkspace& operator=(const BisectWorkspace&) = delete;

    /// Checks out `commit` in the worktree (detached).
    void checkout(const std::string& commit);
    /// Configures (first time only: Release, Ninja, tests off) and builds the `bench` target with `jobs`
    /// parallel jobs (0: ninja's default). Returns the seconds it took. Error(Failure) with the tail of
    /// the build log (`folder`/build.log) when it fails.
    double build(int jobs);
    /// The built binary.
    std::string benchPath() const;
    const std::string& folder() const { return mFolder; }
    std::string buildFolder() const;
    /// Whether ccache was found and is used as the launcher.
    bool usesCcache() const { return mCcache; }

private:
    void removeWorktree() noexcept;
    const GitRepo& mRepo;
    std::string mFolder;
    bool mCcache = false;
    bool mRegistered = false;
};

} // namespace sb
