#include "bench/lib/sweep/SweepRunner.h"

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <unistd.h>

#include "bench/lib/options/RunOptions.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/output/ProgressBar.h"
#include "bench/lib/output/ResultColumns.h"
#include "bench/lib/rows/Environment.h"
#include "bench/lib/sweep/ChildProcess.h"
#include "bench/lib/sweep/InterruptGuard.h"
#include "bench/lib/sweep/ShardLock.h"
#include "bench/lib/sweep/SweepJob.h"
#include "bench/lib/sweep/SweepRows.h"
#include "core/Error.h"
#include "gl/ProgramCache.h"
#include "gl/backends/BackendRegistry.h"
#include "techniques/PropertySet.h"

namespace sb {

namespace {

/// A private directory for the job files, removed with everything in it.
class TempDirectory {
public:
    TempDirectory() {
        std::string pattern = (std::filesystem::temp_directory_path() / "shadowbench-sweep-XXXXXX").string();
        if (!::mkdtemp(pattern.data()))
            throw Error("cannot create a temporary directory for the sweep's job files", ExitCode::Failure);
        mPath = pattern;
    }
    ~TempDirectory() {
        std::error_code ec;
        std::filesystem::remove_all(mPath, ec);
    }
    const std::string& path() const { return mPath; }

private:
    std::string mPath;
};

std::string cell(const CsvTable& t, const std::vector<std::string>& row, const std::string& column) {
    const auto it = std::find(t.header.begin(), t.header.end(), column);
    return it == t.header.end() ? "" : row[size_t(it - t.header.begin())];
}

/// What the CSV already holds of this sweep: the config indices not to run again, the failed ones to
/// run again (--retry-failed), and the wall medians of its ok rows.
struct Done {
    std::set<size_t> indices;
    std::set<size_t> failed;
    std::map<size_t, double> wallMs;
};

std::string shardText(const SweepRunOptions& options) {
    return std::to_string(options.shard) + "/" + std::to_string(options.shardCount);
}

/// The N of a row's shard cell "i/N" ("" when the cell is not one).
std::string splitOf(const std::string& shard) {
    const size_t slash = shard.find('/');
    return slash == std::string::npos ? "" : shard.substr(slash + 1);
}

[[noreturn]] void refuseOtherSweep(const SweepPlan& plan, const SweepRunOptions& options, const CsvTable& t,
                                   const std::vector<std::string>& row) {
    const std::string other = cell(t, row, col::kSweepId);
    throw Error("--csv " + options.csvPath + " holds rows of " +
                (other.empty() ? std::string("a run that is not a sweep")
                               : "sweep " + other + " ('" + cell(t, row, col::kSweepName) + "')") +
                ", not of this sweep " + plan.id() + " ('" + plan.name +
                "'): the definition differs; write to another --csv");
}

// Shards of one split may share a file; a file of another split may not be continued: its groups were
// dealt to shards by another N (SweepPlan::shard), so this shard's rows there are not this shard's work.
void checkSplit(const SweepRunOptions& options, const CsvTable& t, const std::vector<std::string>& row) {
    const std::string theirs = cell(t, row, col::kShard);
    if (theirs.empty() || splitOf(theirs) == std::to_string(options.shardCount))
        return; // empty: says nothing
    throw Error("--csv " + options.csvPath + " holds rows of shard " + theirs + ", a split into " +
                splitOf(theirs) + ", not of --shard " + shardText(options) + " (a split into " +
                std::to_string(options.shardCount) +
                "): a part file of another split cannot be continued; give the --shard it was written "
                "with, or write to another --csv");
}

/// Throws when the file is another sweep's or another split's, or this one's without --resume.
Done readDone(const SweepPlan& plan, const SweepRunOptions& options) {
    Done done;
    if (!std::filesystem::exists(options.csvPath)) return done;
    const CsvTable t = CsvWriter::read(options.csvPath);
    if (t.rows.empty()) return done;
    const std::string id = plan.id();
    for (const auto& row : t.rows) {
        if (cell(t, row, col::kSweepId) != id) refuseOtherSweep(plan, options, t, row);
        checkSplit(options, t, row);
        const size_t index = size_t(std::stoull(cell(t, row, col::kConfigIndex)));
        const std::string status = cell(t, row, col::kStatus);
        if (options.retryFailed && status == col::kStatusFailed)
            done.failed.insert(index);
        else
            done.indices.insert(index);
        if (status == col::kStatusOk) done.wallMs[index] = std::stod(cell(t, row, col::kWallMsMedian));
    }
    // A configuration with a row besides its failed one is done (no retry can make it one row again).
    for (size_t index : done.indices) done.failed.erase(index);
    if (!options.resume)
        throw Error("--csv " + options.csvPath + " already holds " + std::to_string(t.rows.size()) +
                    " rows of this sweep: pass --resume to continue it, or write to another --csv");
    return done;
}

/// The verdict every worker gets; nullopt when the sweep's options say --no-timer-check.
std::optional<TimerVerdict> calibrateOnce(const SweepPlan& plan) {
    const RunConfig config = RunOptions::parseArgs(plan.commonArgs, plan.mode == SweepPlan::Mode::Accuracy
                                                                        ? RunConfig::Mode::Accuracy
                                                                        : RunConfig::Mode::Measure);
    // Vulkan workers calibrate their own device's timestamps (the GL probe would judge another clock).
    if (!config.checkTimer || config.api == RunConfig::Api::Vulkan) return std::nullopt;
    std::unique_ptr<Context> context = createContext(config.context);
    TimerVerdict v;
    {
        ProgramCache programs; // released before the context
        v = TimerTrust::calibrate(programs);
    }
    v.reason += " (calibrated once for the sweep)";
    return v;
}

/// "shadowmap:pcf=3 round 2 @ scene=aircraft ..." for progress lines.
std::string label(const SweepGroup& g, const PlannedRow& r, const std::vector<std::string>& varying) {
    const std::string where = g.describe(&varying);
    return "#" + std::to_string(r.index) + " " + r.technique +
           (r.round > 1 ? " round " + std::to_string(r.round) : "") + (where.empty() ? "" : " @ " + where);
}

std::string lastLine(const std::string& text) {
    std::string t = text;
    while (!t.empty() && (t.back() == '\n' || t.back() == ' ')) t.pop_back();
    const size_t nl = t.rfind('\n');
    return nl == std::string::npos ? t : t.substr(nl + 1);
}

/// Runs one group's pending rows, a fresh worker after each failure.
class GroupRun {
public:
    /// `retrying`: the config indices whose failed row in the CSV a new row replaces (--retry-failed).
    GroupRun(const SweepPlan& plan, const SweepGroup& group, const SweepRunOptions& options,
             const std::optional<TimerVerdict>& timer, const std::string& jobDir, ProgressBar& bar,
             SweepSummary& summary, const std::set<size_t>& retrying)
        : mPlan(plan), mGroup(group), mOptions(options), mTimer(timer), mJobDir(jobDir), mBar(bar),
          mSummary(summary), mRetrying(retrying), mVarying(plan.varyingColumns()) {}

    /// `earlier`: wall medians of rows measured before (their baselines give later rows their ratios).
    void run(std::vector<PlannedRow> pending, const std::map<size_t, double>& earlier) {
        for (const PlannedRow& r : mGroup.rows) {
            const auto it = earlier.find(r.index);
            if (it != earlier.end() && r.technique == mGroup.techniques.front())
                mBaselineWalls[r.round] = it->second;
        }
        while (!pending.empty() && !InterruptGuard::flag()) {
            Attempt a = attempt(pending);
            std::erase_if(pending, [&](const PlannedRow& r) { return a.finished.count(r.index) > 0; });
            if (InterruptGuard::flag() || pending.empty()) return;
            std::vector<PlannedRow> failed = culprits(a, pending);
            recordFailures(failed, a);
            std::erase_if(pending, [&](const PlannedRow& r) {
                return std::any_of(failed.begin(), failed.end(),
                                   [&](const PlannedRow& f) { return f.index == r.index; });
            });
        }
    }

private:
    struct Attempt {
        ChildExit exit;
        std::optional<size_t> begun;
        std::optional<WorkerMessage> failure;
        std::set<size_t> finished;
    };

    Attempt attempt(const std::vector<PlannedRow>& rows) {
        SweepJob job;
        job.mode = mPlan.mode;
        job.args = mPlan.commonArgs;
        job.args.insert(job.args.end(), mGroup.args.begin(), mGroup.args.end());
        job.csvPath = mOptions.csvPath;
        job.tags = SweepRunner::sweepColumns(mPlan, mGroup, mOptions);
        job.baseline = mGroup.techniques.front();
        job.timer = mTimer;
        job.rows = rows;
        job.baselineWalls = mBaselineWalls;
        for (const PlannedRow& r : rows)
            if (mRetrying.count(r.index)) job.replacesFailed.insert(r.index);
        const std::string jobPath = mJobDir + "/group-" + std::to_string(mGroup.index) + ".json";
        job.save(jobPath);
        Attempt a;
        a.exit = ChildProcess::run({ChildProcess::selfExecutable(), "sweep-worker", jobPath}, mGroup.env,
                                   [&](const std::string& line) { onLine(line, rows, a); });
        return a;
    }

    void onLine(const std::string& line, const std::vector<PlannedRow>& rows, Attempt& a) {
        const std::optional<WorkerMessage> m = WorkerMessage::parse(line);
        if (!m) return;
        const auto row =
            std::find_if(rows.begin(), rows.end(), [&](const PlannedRow& r) { return r.index == m->index; });
        if (row == rows.end()) return; // not one of this job's rows: ignore rather than trust it
        switch (m->kind) {
        case WorkerMessage::Kind::Begin:
            a.begun = m->index;
            mBar.setCurrent(label(mGroup, *row, mVarying));
            break;
        case WorkerMessage::Kind::Done:
            a.finished.insert(m->index);
            if (row->technique == mGroup.techniques.front()) mBaselineWalls[row->round] = m->wallMs;
            ++mSummary.ok;
            mBar.finished(label(mGroup, *row, mVarying), true);
            break;
        case WorkerMessage::Kind::Failed:
            a.failure = m;
            break;
        }
    }

    /// The rows a failed attempt is blamed for: the configuration that failed and, when the error is
    /// deterministic (bad input, unsupported), the same technique's later rounds; when the worker died
    /// before it began any row, every pending row (it cannot start on this group at all).
    std::vector<PlannedRow> culprits(const Attempt& a, const std::vector<PlannedRow>& pending) const {
        if (a.exit.ok()) return pending; // ended without reporting them: a protocol failure
        std::optional<size_t> index = a.failure ? std::optional<size_t>(a.failure->index) : a.begun;
        if (!index) return pending;
        const auto row = std::find_if(pending.begin(), pending.end(),
                                      [&](const PlannedRow& r) { return r.index == *index; });
        if (row == pending.end()) return pending;
        const bool deterministic = a.failure && (a.failure->exitCode == int(ExitCode::BadInput) ||
                                                 a.failure->exitCode == int(ExitCode::Unsupported));
        std::vector<PlannedRow> out{*row};
        if (deterministic)
            for (const PlannedRow& r : pending)
                if (r.index != row->index && r.technique == row->technique) out.push_back(r);
        return out;
    }

    std::string message(const Attempt& a) const {
        if (a.failure) return a.failure->message;
        if (a.exit.ok()) return "the worker ended without measuring this configuration";
        const std::string last = lastLine(a.exit.stderrTail);
        return "worker " + a.exit.describe() + (last.empty() ? "" : ": " + last);
    }

    void recordFailures(const std::vector<PlannedRow>& rows, const Attempt& a) {
        const Environment env = Environment::capture();
        const std::string why = message(a);
        // Unsupported here (a missing extension) is a skip, not a failure: the context said no.
        const bool unsupported = a.failure && a.failure->exitCode == int(ExitCode::Unsupported);
        const KeyValues tags = SweepRunner::sweepColumns(mPlan, mGroup, mOptions);
        std::vector<CsvRow> out;
        bool replacing = false;
        for (const PlannedRow& r : rows) {
            replacing = replacing || mRetrying.count(r.index) > 0;
            // What the measured row would have said about itself, as far as it is known without running.
            const TechniqueSpec spec = TechniqueSpec::parse(r.technique);
            const std::string props =
                r.technique.size() > spec.name.size() ? r.technique.substr(spec.name.size() + 1) : "";
            CsvRow row{{col::kTimestamp, Environment::nowIso8601()},
                       {col::kGitCommit, env.gitCommit},
                       {col::kStatus, unsupported ? col::kStatusUnsupported : col::kStatusFailed},
                       {col::kError, why},
                       {col::kTechnique, spec.name},
                       {col::kProperties, props},
                       {col::kTechniqueSpec, r.technique}};
            const CsvRow place = env.placeColumns();
            row.insert(row.end(), place.begin(), place.end());
            row.insert(row.end(), mGroup.columns.begin(), mGroup.columns.end());
            row.insert(row.end(), {{col::kRepeat, std::to_string(r.round)},
                                   {col::kBaseline, mGroup.techniques.front()},
                                   {col::kConfigIndex, std::to_string(r.index)}});
            row.insert(row.end(), tags.begin(), tags.end());
            out.push_back(std::move(row));
            ++(unsupported ? mSummary.unsupported : mSummary.failed);
            mBar.finished(label(mGroup, r, mVarying) + ": " + why, false);
        }
        SweepRows::write(mOptions.csvPath, out, replacing);
    }

    const SweepPlan& mPlan;
    const SweepGroup& mGroup;
    const SweepRunOptions& mOptions;
    const std::optional<TimerVerdict>& mTimer;
    const std::string& mJobDir;
    ProgressBar& mBar;
    SweepSummary& mSummary;
    const std::set<size_t>& mRetrying;
    const std::vector<std::string> mVarying; ///< what tells the groups apart in progress lines
    std::map<int, double> mBaselineWalls;    ///< per round, as far as measured
};

} // namespace

KeyValues SweepRunner::sweepColumns(const SweepPlan& plan, const SweepGroup& group,
                                    const SweepRunOptions& options) {
    KeyValues kv{{col::kSweepId, plan.id()},
                 {col::kSweepName, plan.name},
                 {col::kSweepConfigs, std::to_string(plan.configCount())},
                 {col::kConfigGroup, std::to_string(group.index)},
                 {col::kShard, shardText(options)}};
    kv.insert(kv.end(), group.tags.begin(), group.tags.end());
    return kv;
}

SweepSummary SweepRunner::run(const SweepPlan& plan, const SweepRunOptions& options) {
    CsvWriter::checkWritable(options.csvPath);
    // Before the file is read: a second run of this shard must not even decide what is left to do.
    const ShardLock lock(options.csvPath, options.shard, options.shardCount);
    const Done done = readDone(plan, options);
    SweepSummary summary;
    std::vector<std::pair<const SweepGroup*, std::vector<PlannedRow>>> work;
    for (const SweepGroup* g : plan.shard(options.shard, options.shardCount)) {
        std::vector<PlannedRow> pending;
        for (const PlannedRow& r : g->rows) {
            ++summary.planned;
            if (done.indices.count(r.index)) {
                ++summary.alreadyDone;
            } else {
                pending.push_back(r);
                summary.retried += done.failed.count(r.index);
            }
        }
        if (!pending.empty()) work.emplace_back(g, std::move(pending));
    }
    if (options.checkTimer && !work.empty()) summary.timer = calibrateOnce(plan);
    InterruptGuard interrupts;
    TempDirectory jobs;
    ProgressBar bar(stderr, summary.planned, summary.alreadyDone, options.progress);
    for (auto& [group, pending] : work) {
        GroupRun(plan, *group, options, summary.timer, jobs.path(), bar, summary, done.failed)
            .run(std::move(pending), done.wallMs);
        if (InterruptGuard::flag()) break;
    }
    bar.close();
    summary.interrupted = InterruptGuard::flag() != 0;
    return summary;
}

} // namespace sb
