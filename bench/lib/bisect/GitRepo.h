#pragma once
// The git commands `bench bisect` needs, on one repository, each run as a child process (`git -C DIR
// ...`): resolving commits, the first-parent history between two, and a worktree of its own. Errors
// name the repository and what was asked: an unknown commit or a GOOD that is not an ancestor of BAD is
// sb::Error(BadInput); git itself missing is Unsupported; a git command that fails otherwise is Failure.
#include <string>
#include <vector>

namespace sb {

class GitRepo {
public:
    /// The top of the checkout holding `dir` (`git rev-parse --show-toplevel`), "" when none.
    static std::string toplevelOf(const std::string& dir);
    /// Throws Error(Unsupported) when no `git` runs.
    static void requireGit();

    /// `dir` must be the top of a git checkout (Error(BadInput) otherwise).
    explicit GitRepo(std::string dir);
    const std::string& dir() const { return mDir; }

    /// The full hash of `rev` (a hash, tag, branch, HEAD~3 ...); Error(BadInput) when it names no commit.
    std::string resolve(const std::string& rev) const;
    /// True when `ancestor` is `descendant` or one of its ancestors.
    bool isAncestor(const std::string& ancestor, const std::string& descendant) const;
    /// `git rev-list --first-parent --reverse GOOD..BAD`: the commits after GOOD up to BAD, oldest first.
    std::vector<std::string> firstParentRange(const std::string& good, const std::string& bad) const;
    /// The commit's subject line.
    std::string subject(const std::string& commit) const;

    /// Runs `git -C dir args...` and returns its stdout; Error(Failure) with git's message when it fails.
    std::string run(const std::vector<std::string>& args) const;

private:
    /// The exit code of `git -C dir args...` (stdout kept in `out`, the stderr tail in `err`).
    int tryRun(const std::vector<std::string>& args, std::string& out, std::string& err) const;
    std::string mDir;
};

} // namespace sb
