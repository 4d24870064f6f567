#pragma once
// Runs a SweepPlan: a worker process per group (ChildProcess, SweepWorker), rows appended to
// one CSV as they finish, a progress bar, and the guarantees a long sweep on a shared machine needs:
//  - --resume: rows already in the CSV for this sweep (same sweep_id) are not run again; an interrupted
//    sweep (Ctrl-C, kill, a crash) continues where it stopped and loses nothing it had written. A file
//    of another split (rows whose shard says i/M, resumed as --shard j/N with M != N) is refused: its
//    configurations were dealt to other shards, so resuming it would double some rows and lose others;
//  - --retry-failed (with --resume): configurations whose row says failed are run again, each new row
//    replacing the failed one in one atomic rewrite (bench/lib/sweep/SweepRows.h), so the file keeps
//    one row per configuration; unsupported rows (the context said no) are not retried;
//  - one writer per shard: a lock held for the whole run (bench/lib/sweep/ShardLock.h) refuses a second
//    run of the same shard of the same CSV, naming the holder, before anything is read or written;
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
    bool retryFailed = false; ///< with resume: run the failed configurations again, replacing their rows
    int shard = 1, shardCount = 1;
    bool progress = true;   ///< the progress bar on stderr
    bool checkTimer = true; ///< calibrate once here (false: rows say "unchecked")
};

struct SweepSummary {
    size_t planned = 0;     ///< configurations of this shard
    size_t alreadyDone = 0; ///< found in the CSV (--resume)
    size_t retried = 0;     ///< failed rows found in the CSV and run again (--retry-failed)
    size_t ok = 0, failed = 0;
    /// Rows the GL context cannot run (exit code 3: a missing extension): status=unsupported, not a
    /// failure of the sweep.
    size_t unsupported = 0;
    bool interrupted = false;
    std::optional<TimerVerdict> timer;
};

class SweepRunner {
public:
    /// Runs the shard's configurations that are not in the CSV yet (and, with retryFailed, those whose
    /// row there failed). Throws sb::Error before running anything: Failure when another process runs
    /// this shard of the CSV; BadInput when the CSV belongs to another sweep or another split, or holds
    /// rows of this one without --resume.
    static SweepSummary run(const SweepPlan& plan, const SweepRunOptions& options);
    /// The columns a row of `plan` gets from its group (used by the worker jobs and the failed rows).
    static KeyValues sweepColumns(const SweepPlan& plan, const SweepGroup& group,
                                  const SweepRunOptions& options);
};

} // namespace sb
