#pragma once
// The readable console output: a header saying what runs where (backend, renderer, GL version, scene,
// timer verdict with its evidence), then one table row per technique. GPU columns appear only when the
// timer is trusted, at the start and when re-checked after the runs (a withdrawn verdict is printed again
// above the table). Tables are laid out by TextColumns: a column is as wide as its widest cell.
#include <iosfwd>
#include <vector>

#include "bench/lib/harness/MeasuredHarness.h"
#include "bench/lib/measure/AccuracyEvaluator.h"

namespace sb {

class ConsoleReport {
public:
    static void printHeader(std::ostream& os, const MeasuredHarness& harness);
    /// Either API's run (bench/lib/harness/RowSource.h).
    static void printHeader(std::ostream& os, const RowSource& run);
    static void printTimerVerdict(std::ostream& os, const TimerVerdict& verdict);
    /// The table, one row per measurement. `results` holds `rounds` rounds of the same techniques in
    /// the same order (--repeat; one round without it); with several rounds a column says which. The
    /// ratio column ("vs <first technique>") divides each row's wall median by that of the first
    /// technique of the same round, exactly as the CSV's wall_ratio_vs_baseline does (RunCommand,
    /// Measurement::addRound), so the console and the rows never disagree.
    static void printTable(std::ostream& os, const MeasuredHarness& harness,
                           const std::vector<RunResult>& results, int rounds = 1);
    /// The same with the run's timer verdict given (either API).
    static void printTable(std::ostream& os, const TimerVerdict& verdict,
                           const std::vector<RunResult>& results, int rounds = 1);
    /// After --repeat K: `results` holds K rounds of the same techniques in the same order; prints each
    /// technique's median over the rounds and its ratio to the first technique, taken per round (runs
    /// next to each other) and summarised as median [min, max]: the median of the rows'
    /// wall_ratio_vs_baseline.
    static void printPairedRatios(std::ostream& os, const std::vector<RunResult>& results, int rounds);
    /// `bench accuracy`: time against error, one row per configuration.
    static void printAccuracyTable(std::ostream& os,
                                   const std::vector<std::pair<RunResult, AccuracyResult>>& results);
    /// `bench --list`: techniques with effects, passes, the variants the golden matrix judges in cells of
    /// their own (techniques/MatrixVariant.h), properties (name, type, default, range).
    static void printTechniqueList(std::ostream& os);
    /// The Vulkan devices the loader sees (indices for --vk-device), or why there are none.
    static void printVulkanDevices(std::ostream& os);
};

} // namespace sb
