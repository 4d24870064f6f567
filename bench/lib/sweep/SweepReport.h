#pragma once
// What `bench sweep` prints: the plan (--dry-run), the summary after a run, and the rows of the run
// read back from the CSV for --format.
#include <iosfwd>

#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/sweep/SweepRunner.h"

namespace sb {

class SweepReport {
public:
    /// The options every run gets, then every configuration with its index, group and shard (those of
    /// `shard` marked).
    static void printPlan(std::ostream& os, const SweepPlan& plan, int shard, int shardCount);
    /// Counts, failures (first few with their messages), where the rows are, how to continue.
    static void printSummary(std::ostream& os, const SweepPlan& plan, const SweepRunOptions& options,
                             const SweepSummary& summary);
    /// The CSV's rows of this sweep and shard.
    static CsvTable shardRows(const SweepPlan& plan, const SweepRunOptions& options);
};

} // namespace sb
