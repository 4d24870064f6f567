#pragma once
// Runs one configuration of the gate's suite (CiSuite.h) in its own `bench` process and returns its
// row. A process per run, as a sweep's workers: base and head may be different binaries or run under
// different environments (a driver A/B through LD_LIBRARY_PATH, LP_NUM_THREADS), and a run under
// valgrind needs a process of its own anyway. Runs skip the GPU-timer calibration (--no-timer-check):
// no layer of the gate reads GPU times, and the measured frames then issue no timer queries.
#include <string>
#include <utility>
#include <vector>

#include "bench/lib/gate/CiSuite.h"
#include "bench/lib/output/CsvWriter.h"

namespace sb {

/// One side of a comparison: which binary, with which environment.
struct CiSide {
    std::string label; ///< "head", "base"
    std::string bench; ///< path of the bench executable
    std::vector<std::pair<std::string, std::string>> env;
    /// "head (LP_NUM_THREADS=1)"
    std::string describe() const;
};

struct CiRunRequest {
    int frames = 1;
    int warmup = 0;
    std::vector<std::string> wrapper; ///< argv prefix (valgrind ...), empty to run bench directly
    std::vector<std::pair<std::string, std::string>> env; ///< on top of the side's
};

class SuiteRunner {
public:
    /// The configuration's one row, with `ci_config` and `ci_side` in front. A run that does not end
    /// with exit code 0 and one row with status ok throws sb::Error(Failure) naming the configuration,
    /// the side, how the process ended and its last stderr lines.
    static CsvRow run(const CiSuite& suite, const CiConfig& config, const CiSide& side,
                      const CiRunRequest& request);
    /// The bench options of a run: the suite's (minus those the configuration gives itself), the
    /// configuration's, the frame counts and --no-timer-check; no binary, no output format.
    static std::vector<std::string> benchArgs(const CiSuite& suite, const CiConfig& config, int frames,
                                              int warmup);
    /// The argv run() starts (for the report's "reproduce" line and for tests).
    static std::vector<std::string> argv(const CiSuite& suite, const CiConfig& config, const CiSide& side,
                                         const CiRunRequest& request);
};

} // namespace sb
