#include "bench/lib/sweep/SweepReport.h"

#include <algorithm>
#include <ostream>

#include "bench/lib/output/ProgressBar.h"
#include "bench/lib/output/ResultColumns.h"
#include "core/Strings.h"

namespace sb {

namespace {
constexpr size_t kFailuresShown = 5;

size_t column(const CsvTable& t, const std::string& name) {
    return size_t(std::find(t.header.begin(), t.header.end(), name) - t.header.begin());
}
} // namespace

void SweepReport::printPlan(std::ostream& os, const SweepPlan& plan, int shard, int shardCount) {
    os << "sweep '" << plan.name << "' (" << plan.id() << ", " << SweepPlan::modeName(plan.mode)
       << "): " << plan.groups.size() << " combinations, " << plan.configCount() << " configurations\n";
    // What every run gets besides its combination's axes: where the file's and the command line's
    // --frames, --warmup ... ended up.
    if (!plan.commonArgs.empty()) os << "every run: " << join(plan.commonArgs, " ") << "\n";
    for (const SweepGroup& g : plan.groups) {
        const int owner = int(g.index % size_t(shardCount)) + 1;
        os << (owner == shard ? "* " : "  ") << "group " << g.index << " (shard " << owner << "/"
           << shardCount << "): " << g.describe();
        for (const auto& [k, v] : g.env) os << " " << k << "=" << v;
        os << "\n";
        for (const PlannedRow& r : g.rows)
            os << "      #" << r.index << " " << r.technique << " round " << r.round << "\n";
    }
    if (shardCount > 1) os << "(* = in shard " << shard << "/" << shardCount << ")\n";
}

void SweepReport::printSummary(std::ostream& os, const SweepPlan& plan, const SweepRunOptions& options,
                               const SweepSummary& s) {
    os << "sweep '" << plan.name << "' (" << plan.id() << ")";
    if (options.shardCount > 1) os << " shard " << options.shard << "/" << options.shardCount;
    os << ": " << s.planned << " configurations, " << s.ok << " measured, " << s.failed << " failed";
    if (s.unsupported) os << ", " << s.unsupported << " unsupported here (skipped)";
    if (s.alreadyDone) os << ", " << s.alreadyDone << " done before";
    if (s.retried) os << ", " << s.retried << " failed before and run again";
    os << "\n";
    if (s.timer) os << "GPU timer " << s.timer->label() << ": " << s.timer->reason << "\n";
    if (s.failed || s.unsupported) {
        const CsvTable t = shardRows(plan, options);
        const size_t status = column(t, col::kStatus), error = column(t, col::kError),
                     index = column(t, col::kConfigIndex);
        size_t shown = 0;
        for (const auto& row : t.rows) {
            if (status >= row.size() || row[status] == col::kStatusOk || shown == kFailuresShown) continue;
            os << "  " << row[status] << " #" << (index < row.size() ? row[index] : "?") << ": "
               << (error < row.size() ? row[error] : "") << "\n";
            ++shown;
        }
    }
    os << "rows in " << options.csvPath << "\n";
    if (s.interrupted)
        os << "interrupted: run the same command with --resume to continue (nothing written is lost)\n";
}

CsvTable SweepReport::shardRows(const SweepPlan& plan, const SweepRunOptions& options) {
    CsvTable t = CsvWriter::read(options.csvPath);
    const size_t id = column(t, col::kSweepId), shard = column(t, col::kShard);
    const std::string wantId = plan.id();
    const std::string wantShard = std::to_string(options.shard) + "/" + std::to_string(options.shardCount);
    std::erase_if(t.rows, [&](const std::vector<std::string>& row) {
        return id >= row.size() || row[id] != wantId || shard >= row.size() || row[shard] != wantShard;
    });
    return t;
}

} // namespace sb
