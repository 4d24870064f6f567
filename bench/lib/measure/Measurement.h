#pragma once
// One measured configuration: the timing of a technique on a prepared harness, its judgement against
// the reference when asked for, and the CSV row of both. `bench`, `bench accuracy` and the sweep
// workers all measure through here, so a row means the same whichever command wrote it.
#include <optional>

#include "bench/lib/harness/MeasuredHarness.h"
#include "bench/lib/measure/AccuracyEvaluator.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/rows/Environment.h"

namespace sb {

struct Measurement {
    RunResult run;
    std::optional<AccuracyResult> accuracy;
    CsvRow row;

    /// Measures `technique` (MeasuredHarness::measure), judges it when `evaluator` is not null, and builds
    /// the row (its timestamp is set to now). On the evaluator's own harness (any API) the judgement
    /// renders what it needs (perturbations, the path); on another harness it judges the census frame's
    /// visibility at the evaluator's samples, without the stability perturbations.
    static Measurement take(MeasuredHarness& harness, Technique& technique, AccuracyEvaluator* evaluator,
                            const AccuracyOptions& options, Environment& env);
    /// Adds the interleaving columns: `repeat` (the round) and, when `baselineWallMs` is given, the
    /// baseline's spec and this row's wall median over the baseline's of the same round.
    void addRound(int round, const std::string& baseline, std::optional<double> baselineWallMs);
};

} // namespace sb
