#pragma once
// One bisection of `bench bisect`: GOOD's build measured as the reference, then a first-parent binary
// search (BisectSearch.h) over GOOD..BAD, each probed commit checked out into the one worktree, built
// in the one build folder (BisectWorkspace.h) and measured once (BisectSignal.h). A commit that does not
// build or run is skipped, with its reason. Progress goes to stderr, a line per commit: its step of at
// most ceil(log2 N) + 1, hash, subject, verdict, build and run time.
#include <csignal>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/lib/bisect/BisectSearch.h"
#include "bench/lib/bisect/BisectSignal.h"
#include "bench/lib/bisect/BisectWorkspace.h"
#include "bench/lib/bisect/GitRepo.h"

namespace sb {

/// One commit that was built (and, if that worked, measured).
struct BisectStep {
    std::string commit, subject;
    std::string verdict; ///< "reference" (GOOD), "same", "changed", "skipped"
    double buildSeconds = 0, runSeconds = 0;
    std::string reason;               ///< skipped: why (the build's or run's message)
    SignalValue value;                ///< empty when skipped
    std::vector<std::string> changes; ///< "changed": how it differs from GOOD
};

struct BisectResult {
    std::string good, bad;            ///< full hashes
    std::vector<std::string> commits; ///< GOOD..BAD, oldest first
    BisectOutcome outcome;
    std::vector<BisectStep> steps; ///< in build order, GOOD first
    double totalSeconds = 0;
    std::string buildFolder;

    /// The step of `commit`, or null when it was not built.
    const BisectStep* step(const std::string& commit) const;
    /// The JSON of --json (docs/USAGE.md "Bisect").
    nlohmann::json toJson(const std::string& signal, const std::vector<std::string>& benchArgs) const;
};

class Bisection {
public:
    Bisection(const GitRepo& repo, BisectWorkspace& workspace, const BisectSignal& signal, int jobs);
    /// Runs the search; Error(Failure) when GOOD itself does not build or run (no reference), and when
    /// `interrupted` reads true after a child returns (SIGINT: the worktree is cleaned up as it unwinds).
    BisectResult run(const std::string& good, const std::string& bad,
                     const volatile std::sig_atomic_t& interrupted);

private:
    /// Checks out, builds and measures one commit; a build or run that fails is a skipped step.
    BisectStep measure(const std::string& commit, const volatile std::sig_atomic_t& interrupted);
    const GitRepo& mRepo;
    BisectWorkspace& mWorkspace;
    const BisectSignal& mSignal;
    int mJobs;
};

} // namespace sb
