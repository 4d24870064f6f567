#pragma once
// Layer C of the perf gate: wall time, measured side by side. Per round every configuration runs once
// on each side, in ABBA (or seeded random) order per round (bench/lib/gate/Interleave.h), each run a process
// of its own; the round's value is the run's median frame wall time. The A/A control (the base side
// against itself, or the head against itself when there is no base) runs in the same rounds. Each
// configuration gets WallTimeStats and a WallTimeVerdict at its share of the family-wise alpha
// (Bonferroni), and the report says what the job could see: the control's noise and the minimum
// detectable effect at this many rounds.
#include <optional>
#include <string>
#include <vector>

#include "bench/lib/gate/CiSuite.h"
#include "bench/lib/gate/GateReport.h"
#include "bench/lib/gate/Interleave.h"
#include "bench/lib/gate/SuiteRunner.h"

namespace sb {

struct WallLayerOptions {
    int rounds = 9;
    uint64_t seed = 1;
    ci::Scheme scheme = ci::Scheme::Abba;
    /// One false alarm a week at 20 gated runs a week: 0.05 per run, split over the configurations
    /// (Bonferroni), about 0.005 each for a suite of ten.
    double familyAlpha = 0.05;
    double floor = 0.05; ///< the smallest slowdown that may fail
};

struct WallLayerResult {
    GateLayer layer;
    std::vector<std::pair<std::string, LayerCell>> cells; ///< per configuration
    std::vector<CsvRow> runs;                             ///< every run's row (with ci_round)
};

class WallLayer {
public:
    /// `base` empty: the head against itself only (the control), reported as what the job could see.
    /// Throws Error(BadInput) unless `familyAlpha` is in [1e-9, 0.5] and `floor` in [0, 10], both finite:
    /// CLI11's range check lets nan through (every comparison with nan is false), and a nan floor would
    /// make the layer unable to fail.
    static void checkThresholds(double familyAlpha, double floor);
    static WallLayerResult run(const CiSuite& suite, const std::vector<const CiConfig*>& configs,
                               const std::optional<CiSide>& base, const CiSide& head,
                               const WallLayerOptions& options);
};

} // namespace sb
