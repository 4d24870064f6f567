#pragma once
// The readable console output: a header saying what runs where (backend, renderer, GL version, scene,
// timer verdict with its evidence), then one table row per technique. GPU columns appear only when the
// timer is trusted, at the start and when re-checked after the runs (a withdrawn verdict is printed again
// above the table).
#include <iosfwd>
#include <vector>

#include "bench/run/AccuracyEvaluator.h"
#include "bench/run/Harness.h"

namespace sb {

class ConsoleReport {
public:
    static void printHeader(std::ostream& os, const Harness& harness);
    static void printTimerVerdict(std::ostream& os, const TimerVerdict& verdict);
    /// The table; ratios are taken against the `none` row when there is one (the overhead baseline).
    static void printTable(std::ostream& os, const Harness& harness, const std::vector<RunResult>& results);
    /// After --repeat K: `results` holds K rounds of the same techniques in the same order; prints each
    /// technique's median over the rounds and its ratio to the first technique, taken per round (runs
    /// next to each other) and summarised as median [min, max].
    static void printPairedRatios(std::ostream& os, const std::vector<RunResult>& results, int rounds);
    /// `bench accuracy`: time against error, one row per configuration.
    static void printAccuracyTable(std::ostream& os,
                                   const std::vector<std::pair<RunResult, AccuracyResult>>& results);
    /// `bench --list`: techniques with effects, passes, properties (name, type, default, range).
    static void printTechniqueList(std::ostream& os);
};

} // namespace sb
