#pragma once
// The measurements `-t auto` chooses from (bench/lib/select/AutoSelection.h): for the harness's scene,
// camera, size and submission on the current renderer, each candidate technique (every registered one
// with its default properties, except the reference, which is the judge, and the synthetic calibration
// workloads; on a scene whose point light casts shadows, hybrid with each omni map as its cast part,
// techniques/PointLightRefusal.h, instead of its default, whose cast part refuses that light) is prepared,
// then all of them are timed in interleaved rounds, one frame of each per round after a warm-up frame (so
// load that comes and goes falls on all alike; the cost is the median, the rounds are kept for
// AutoSelection's every-round comparison), their exact work counted in one census frame (vertex plus fragment
// shader invocations), and each judged against the Embree reference on every light (samples misclassified at
// 0.5 as a share of those the reference shadows: the misplaced share of the shadow, the worst light). A
// candidate that refuses the configuration is kept with its refusal. Results are cached in a CSV keyed by
// renderer, GL version, scene hash, size, camera, submission and the candidate's canonical spec, so a second
// run on the same machine measures nothing;
// --recalibrate measures again, and a cache file written by hand injects costs (the tests do).
#include <iosfwd>
#include <string>
#include <vector>

#include "bench/lib/harness/Harness.h"
#include "bench/lib/select/AutoSelection.h"

namespace sb {

struct CalibrationOptions {
    std::string cachePath; ///< "" = defaultCachePath()
    bool refresh = false;  ///< measure every candidate again (and replace its cached row)
    int frames = 5;        ///< interleaved rounds: timed frames per candidate
    int warmup = 1;
};

class Calibration {
public:
    /// $XDG_CACHE_HOME/shadowbench/auto-calibration.csv, else ~/.cache/shadowbench/..., else
    /// ./auto-calibration.csv.
    static std::string defaultCachePath();
    /// The candidates, measured here or read from the cache (what came from where goes to `log`).
    static std::vector<AutoCandidate> candidates(Harness& harness, const CalibrationOptions& options,
                                                 std::ostream& log);
    /// The cache key of candidate `spec` on `harness` (the columns a cached row must match).
    static CsvRow keyColumns(const Harness& harness, const std::string& spec);
};

} // namespace sb
