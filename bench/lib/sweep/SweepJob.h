#pragma once
// What the sweep runner hands one worker process (`bench sweep-worker JOB.json`) and what the worker
// says back. The job is a file rather than a command line so that technique specs, tags and the timer
// verdict travel without quoting rules; the answer is a line protocol on the worker's stdout:
//   @sb begin <config_index>
//   @sb done <config_index> <wall median ms>
//   @sb failed <config_index> <exit code> <one-line message>
// A worker that dies without "done" or "failed" for the configuration it began has crashed in it.
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "bench/lib/harness/TimerTrust.h"
#include "bench/lib/sweep/SweepPlan.h"

namespace sb {

struct SweepJob {
    SweepPlan::Mode mode = SweepPlan::Mode::Measure;
    std::vector<std::string> args; ///< the run's options (common + group), without -t
    std::string csvPath;
    KeyValues tags;                    ///< columns added to every row (sweep_id ... perturbation)
    std::string baseline;              ///< the group's first technique: ratios are taken against it
    std::optional<TimerVerdict> timer; ///< measured once by the runner; absent: the worker calibrates
    std::vector<PlannedRow> rows;      ///< to measure, in this order
    /// Wall medians of baseline rows measured by an earlier worker (--resume, a respawn after a
    /// failure), per round, so the rows of those rounds still get their ratio.
    std::map<int, double> baselineWalls;
    /// The config indices whose failed row in the CSV this job's row replaces (--retry-failed).
    std::set<size_t> replacesFailed;

    void save(const std::string& path) const;
    static SweepJob load(const std::string& path);
};

/// One parsed protocol line.
struct WorkerMessage {
    enum class Kind { Begin, Done, Failed } kind;
    size_t index = 0;
    double wallMs = 0.0; ///< Done
    int exitCode = 0;    ///< Failed
    std::string message; ///< Failed
    /// nullopt for lines that are not protocol lines (they are ignored).
    static std::optional<WorkerMessage> parse(const std::string& line);
    static std::string begin(size_t index);
    static std::string done(size_t index, double wallMs);
    static std::string failed(size_t index, int exitCode, const std::string& message);
};

} // namespace sb
