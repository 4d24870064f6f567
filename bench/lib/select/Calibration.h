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
// candidate that refuses the configuration is kept with its refusal. On Vulkan (a VulkanHarness) the
// candidates are the techniques' Vulkan forms, timed, counted and judged on the Vulkan harness (its own
// G-buffer places the reference's samples, as bench accuracy --api vulkan judges); a technique without a
// form on the harness's API is skipped with a line saying so. Results are
// cached in a CSV keyed by API (Vulkan rows say api vulkan; GL's rows have no api or gl), renderer (the
// Vulkan device), GL version (Vulkan: its API version and driver), scene hash, size, camera, submission and
// the candidate's canonical spec, so GL's and Vulkan's measurements never mix and a second run on the same
// machine measures nothing;
// --recalibrate measures again, and a cache file written by hand injects costs (the tests do).
// A seed (--calibration-seed) is a calibration read before the cache and never written: the perf
// suite's committed results/ci/auto-calibration.csv, which keeps -t auto's choice, and so its exact work,
// the same on every run on the machine it was measured on. What a run measures goes to the cache, which
// lives in the user's cache folder, never in the source tree: a benchmark run does not modify
// committed results.
#include <iosfwd>
#include <string>
#include <vector>

#include "bench/lib/harness/Harness.h"
#include "bench/lib/select/AutoSelection.h"

namespace sb {

struct CalibrationOptions {
    std::string cachePath; ///< "" = defaultCachePath()
    /// "" = none. Rows read before the cache's, never written. A relative path not found from the
    /// working directory is looked up where bench finds its data (Paths::findResource: the build's or
    /// installed tree), so a suite naming results/ci/... runs from any folder.
    std::string seedPath;
    bool refresh = false; ///< measure every candidate again (and replace its cached row)
    int frames = 5;       ///< interleaved rounds: timed frames per candidate
    int warmup = 1;
};

class Calibration {
public:
    /// $XDG_CACHE_HOME/shadowbench/auto-calibration.csv, else ~/.cache/shadowbench/..., else (neither
    /// variable set) the system's temporary folder's shadowbench/...: never the working directory, which
    /// may be the source tree.
    static std::string defaultCachePath();
    /// The candidates, read from the seed, else from the cache, else measured here and appended to the
    /// cache (what came from where goes to `log`). Throws Error(BadInput) for a seed that does not exist.
    /// Every candidate is timed, counted and judged on `harness` (GL or Vulkan).
    static std::vector<AutoCandidate> candidates(MeasuredHarness& harness, const CalibrationOptions& options,
                                                 std::ostream& log);
    /// The cache key of candidate `spec` on `harness` (the columns a cached row must match).
    static CsvRow keyColumns(const MeasuredHarness& harness, const std::string& spec);
};

} // namespace sb
