#pragma once
// Runs a SweepPlan: a worker process per group (ChildProcess, SweepWorker), rows appended to
// one CSV as they finish, a progress bar, and the guarantees a long sweep on a shared machine needs:
//  - --resume: rows already in the CSV for this sweep (same sweep_id) are not run again; an interrupted
//    sweep (Ctrl-C, kill, a crash) continues where it stopped and loses nothing it had written;
//  - a configuration that fails (GL error, unsupported, crash of the worker) gets a row with
//    status "failed" and its message, and the sweep goes on with a fresh worker;
//  - --shard i/N runs a deterministic slice (SweepPlan::shard); `bench merge` joins the shards' CSVs;
//  - the GPU-timer verdict is measured once, in this process, and handed to every worker (each worker
//    calibrating again would cost ~0.5 s per group on llvmpipe and measure the same driver).
// Every row carries sweep_id, sweep_name, sweep_configs, config_index, config_group and shard.
#include <cstddef>
#include <optional>
#include <string>

#include "bench/lib/harness/TimerTrust.h"
#include "bench/lib/sweep/SweepPlan.h"

namespace sb {

struct SweepRunOptions {
    std::string csvPath;
    bool resume = false;
    int shard = 1, shardCount = 1;
    bool progress = true;   ///< the progress bar on stderr
    bool checkTimer = true; ///< calibrate once here (false: rows say "unchecked")
};

struct SweepSummary {
    size_t planned = 0;     ///< configurations of this shard
    size_t alreadyDone = 0; ///< found in the CSV (--resume)
    size_t ok = 0, failed = 0;
    /// Rows the GL context cannot run (exit code 3: a missing extension): status=unsupported, not a
    /// failure of the sweep.
    size_t unsupported = 0;
    bool interrupted = false;
    std::optional<TimerVerdict> timer;
};

class SweepRunner {
public:
    /// Runs the shard's configurations that are not in the CSV yet. Throws sb::Error before running
    /// anything when the CSV belongs to another sweep, or holds rows of this one without --resume.
    static SweepSummary run(const SweepPlan& plan, const SweepRunOptions& options);
    /// The columns a row of `plan` gets from its group (used by the worker jobs and the failed rows).
    static KeyValues sweepColumns(const SweepPlan& plan, const SweepGroup& group,
                                  const SweepRunOptions& options);
};

} // namespace sb
