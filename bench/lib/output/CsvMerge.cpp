#include "bench/lib/output/CsvMerge.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <filesystem>
#include <map>
#include <optional>
#include <system_error>

#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/output/ResultColumns.h"
#include "core/Error.h"

namespace sb {

namespace {

namespace fs = std::filesystem;

// The sweep refuses more than --max-configs rows (10000 unless raised); a trillion rows at a millisecond
// each would take 30 years, so a larger sweep_configs is a damaged cell, not a sweep.
constexpr size_t kMaxSweepConfigs = 1000000000000;

// Every refusal is about what the user handed in; the message is the one line printed before exit 2.
[[noreturn]] void fail(const std::string& message) {
    throw Error(message, ExitCode::BadInput);
}

std::string inQuotes(const std::string& s) {
    return "'" + s + "'";
}

// ---------------------------------------------------------------------------------------------------
// Inputs

struct SweepColumns {
    size_t id, configs, index, shard;
};

struct Input {
    std::string path;
    CsvTable table;
    SweepColumns columns{};
    std::vector<size_t> lines; ///< the line each row starts on, for messages
};

std::optional<size_t> optionalColumn(const Input& in, const char* column) {
    auto it = std::find(in.table.header.begin(), in.table.header.end(), column);
    if (it == in.table.header.end()) return std::nullopt;
    return size_t(it - in.table.header.begin());
}

size_t countNewlines(const std::vector<std::string>& cells) {
    size_t n = 0;
    for (const std::string& cell : cells) n += size_t(std::count(cell.begin(), cell.end(), '\n'));
    return n;
}

// CsvTable forgets where rows were, but CsvWriter writes one line per record plus one per newline
// inside a quoted cell, so the lines can be recounted. (A hand-edited file with blank lines would
// shift them; the row is still easy to find from its cells.)
std::vector<size_t> rowLines(const CsvTable& table) {
    std::vector<size_t> lines;
    size_t line = 2 + countNewlines(table.header);
    for (const auto& row : table.rows) {
        lines.push_back(line);
        line += 1 + countNewlines(row);
    }
    return lines;
}

size_t requireColumn(const Input& in, const char* column) {
    auto it = std::find(in.table.header.begin(), in.table.header.end(), column);
    if (it == in.table.header.end())
        fail(inQuotes(in.path) + " is not a sweep CSV: column " + inQuotes(column) + " missing");
    return size_t(it - in.table.header.begin());
}

Input readInput(const std::string& path) {
    Input in{path, CsvWriter::read(path), {}, {}};
    in.columns = {requireColumn(in, col::kSweepId), requireColumn(in, col::kSweepConfigs),
                  requireColumn(in, col::kConfigIndex), requireColumn(in, col::kShard)};
    in.lines = rowLines(in.table);
    return in;
}

// Comparing canonical paths catches "out.csv" vs "./results/../out.csv" and symlinks to the output;
// weakly_canonical also works for an output that does not exist yet.
fs::path canonical(const std::string& path) {
    std::error_code ec;
    fs::path p = fs::weakly_canonical(path, ec);
    return ec ? fs::absolute(path).lexically_normal() : p;
}

void checkPaths(const std::vector<std::string>& inputs, const std::string& output,
                const MergeOptions& options) {
    if (inputs.empty()) fail("merge: no input files given");
    fs::path out = canonical(output);
    std::map<fs::path, std::string> seen;
    for (const std::string& input : inputs) {
        fs::path in = canonical(input);
        if (in == out) fail("input " + inQuotes(input) + " is also the output file " + inQuotes(output));
        auto [it, inserted] = seen.emplace(in, input);
        if (!inserted)
            fail("input " + inQuotes(input) + " is given twice (also as " + inQuotes(it->second) + ")");
    }
    std::error_code ec;
    if (!options.force && fs::symlink_status(output, ec).type() != fs::file_type::not_found)
        fail("output " + inQuotes(output) + " exists; pass --force to replace it");
}

// ---------------------------------------------------------------------------------------------------
// Sweep cells

// Plain digits only: "+3", " 3", "3.0" and "0x3" are not how the bench writes an index.
std::optional<size_t> parseCount(const std::string& s) {
    if (s.empty() || !std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return std::nullopt;
    size_t v = 0;
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
    return v;
}

struct ShardSpec {
    size_t index, count;
};

std::optional<ShardSpec> parseShard(const std::string& s) {
    size_t slash = s.find('/');
    if (slash == std::string::npos) return std::nullopt;
    std::optional<size_t> i = parseCount(s.substr(0, slash));
    std::optional<size_t> n = parseCount(s.substr(slash + 1));
    if (!i || !n || *i < 1 || *i > *n) return std::nullopt;
    return ShardSpec{*i, *n};
}

/// A sweep-wide value and where it was first seen, so a conflict can name both places.
struct FirstSeen {
    std::string value, where;
};

// Walks all rows once, checking each against what earlier rows (of any file) established.
class SweepCheck {
public:
    void add(const Input& in, size_t row) {
        const std::vector<std::string>& cells = in.table.rows[row];
        std::string where = in.path + ":" + std::to_string(in.lines[row]);
        const std::string& id = cells[in.columns.id];
        if (id.empty()) fail(where + ": empty " + col::kSweepId);
        agree(mId, id, where, "rows of different sweeps mixed: sweep_id");
        size_t configs = requireConfigs(cells[in.columns.configs], where);
        size_t index = requireIndex(cells[in.columns.index], configs, where);
        ShardSpec shard = requireShard(cells[in.columns.shard], where);
        agree(mShardCount, std::to_string(shard.count), where,
              "shards of different splits mixed: shard count");
        auto [it, inserted] = mWhere.emplace(index, where);
        if (!inserted)
            fail("configuration " + std::to_string(index) + " appears twice: in " + inQuotes(it->second) +
                 " and " + inQuotes(where) + "; keep one of the rows");
    }

    std::string sweepId() const { return mId ? mId->value : ""; }
    size_t configs() const { return mConfigs ? *parseCount(mConfigs->value) : 0; }
    size_t shardCount() const { return mShardCount ? *parseCount(mShardCount->value) : 0; }
    const std::map<size_t, std::string>& seenIndices() const { return mWhere; }

private:
    static void agree(std::optional<FirstSeen>& first, const std::string& value, const std::string& where,
                      const std::string& what) {
        if (!first)
            first = FirstSeen{value, where};
        else if (first->value != value)
            fail(what + " " + inQuotes(first->value) + " in " + inQuotes(first->where) + " but " +
                 inQuotes(value) + " in " + inQuotes(where));
    }

    size_t requireConfigs(const std::string& cell, const std::string& where) {
        std::optional<size_t> configs = parseCount(cell);
        if (!configs || *configs < 1)
            fail(where + ": " + col::kSweepConfigs + " " + inQuotes(cell) + " is not a positive integer");
        if (*configs > kMaxSweepConfigs)
            fail(where + ": " + col::kSweepConfigs + " " + inQuotes(cell) + " is more than " +
                 std::to_string(kMaxSweepConfigs) + " configurations, more than any sweep measures");
        // Compared as numbers: "048" and "48" are the same sweep.
        agree(mConfigs, std::to_string(*configs), where, "rows of different sweeps mixed: sweep_configs");
        return *configs;
    }

    static size_t requireIndex(const std::string& cell, size_t configs, const std::string& where) {
        std::optional<size_t> index = parseCount(cell);
        if (!index || *index >= configs)
            fail(where + ": " + col::kConfigIndex + " " + inQuotes(cell) + " is not an integer in [0, " +
                 std::to_string(configs) + ")");
        return *index;
    }

    static ShardSpec requireShard(const std::string& cell, const std::string& where) {
        std::optional<ShardSpec> shard = parseShard(cell);
        if (!shard)
            fail(where + ": " + col::kShard + " " + inQuotes(cell) + " is not \"i/N\" with 1 <= i <= N");
        return *shard;
    }

    std::optional<FirstSeen> mId, mConfigs, mShardCount;
    std::map<size_t, std::string> mWhere; ///< config_index -> where its row is
};

// Walks the gaps between the indices seen: the ranges are at most one more than the rows, whatever
// sweep_configs says, so a cell claiming a billion configurations costs nothing.
std::vector<std::pair<size_t, size_t>> missingRanges(const SweepCheck& check, size_t& count) {
    std::vector<std::pair<size_t, size_t>> ranges;
    count = 0;
    size_t next = 0; // the first index not yet accounted for
    auto gapUpTo = [&](size_t end) {
        if (end > next) {
            ranges.emplace_back(next, end - 1);
            count += end - next;
        }
    };
    for (const auto& seen : check.seenIndices()) {
        gapUpTo(seen.first);
        next = seen.first + 1;
    }
    gapUpTo(check.configs());
    return ranges;
}

// The facts only: whether they refuse the merge or warn beside a written one is the caller's to say.
std::string incompleteText(const MergeReport& report) {
    std::string text;
    if (report.missingCount)
        text = std::to_string(report.missingCount) + " of " + std::to_string(report.configs) +
               " configurations missing (indices " + ShardGaps::rangesText(report.missing) + ")";
    if (report.failedRows)
        text += (text.empty() ? std::to_string(report.failedRows) + " of " + std::to_string(report.configs) +
                                    " configurations"
                              : ", " + std::to_string(report.failedRows)) +
                " failed (indices " + ShardGaps::rangesText(report.failed) + ")";
    return text;
}

// ---------------------------------------------------------------------------------------------------
// Output

struct IndexedRow {
    size_t configIndex;
    std::vector<std::string> cells; ///< in the merged header's order
};

std::vector<std::string> unionHeader(const std::vector<Input>& inputs) {
    std::vector<std::string> header;
    for (const Input& in : inputs)
        for (const std::string& column : in.table.header)
            if (std::find(header.begin(), header.end(), column) == header.end()) header.push_back(column);
    return header;
}

CsvTable mergedTable(const std::vector<Input>& inputs) {
    CsvTable out{unionHeader(inputs), {}};
    std::vector<IndexedRow> rows;
    for (const Input& in : inputs) {
        std::vector<size_t> target; // input column -> merged column
        for (const std::string& column : in.table.header)
            target.push_back(
                size_t(std::find(out.header.begin(), out.header.end(), column) - out.header.begin()));
        for (const auto& row : in.table.rows) {
            IndexedRow merged{*parseCount(row[in.columns.index]),
                              std::vector<std::string>(out.header.size())};
            for (size_t c = 0; c < row.size(); ++c) merged.cells[target[c]] = row[c];
            rows.push_back(std::move(merged));
        }
    }
    std::sort(rows.begin(), rows.end(),
              [](const IndexedRow& a, const IndexedRow& b) { return a.configIndex < b.configIndex; });
    for (IndexedRow& row : rows) out.rows.push_back(std::move(row.cells));
    return out;
}

// ---------------------------------------------------------------------------------------------------
// Outcomes

// Failed unless known to be ok or unsupported: a file without `status` says of no row that it is ok.
bool rowFailed(const std::vector<std::string>& row, std::optional<size_t> status) {
    return !status || (row[*status] != col::kStatusOk && row[*status] != col::kStatusUnsupported);
}

/// Every row's index, group, shard and outcome, for ShardGaps; counts the unsupported rows on the way.
std::vector<RowPlace> rowPlaces(const std::vector<Input>& inputs, size_t& unsupported) {
    std::vector<RowPlace> places;
    unsupported = 0;
    for (const Input& in : inputs) {
        const std::optional<size_t> group = optionalColumn(in, col::kConfigGroup);
        const std::optional<size_t> status = optionalColumn(in, col::kStatus);
        for (const auto& row : in.table.rows) {
            RowPlace p;
            p.index = *parseCount(row[in.columns.index]); // checked by SweepCheck
            p.group = group ? parseCount(row[*group]) : std::nullopt;
            p.shard = parseShard(row[in.columns.shard])->index;
            p.failed = rowFailed(row, status);
            unsupported += status && row[*status] == col::kStatusUnsupported;
            places.push_back(p);
        }
    }
    return places;
}

IndexRanges failedRanges(const std::vector<RowPlace>& places) {
    std::vector<size_t> indices;
    for (const RowPlace& p : places)
        if (p.failed) indices.push_back(p.index);
    std::sort(indices.begin(), indices.end());
    IndexRanges ranges;
    for (size_t i : indices) {
        if (!ranges.empty() && ranges.back().second + 1 == i)
            ranges.back().second = i;
        else
            ranges.emplace_back(i, i);
    }
    return ranges;
}

// ---------------------------------------------------------------------------------------------------
// Part files

/// A file name with a shard number in it, split around the number: "out/part" + "3" + ".csv".
struct NameTemplate {
    std::string before, after;
    bool operator==(const NameTemplate&) const = default;
};

/// `path` split around `number` where that number appears in the file name exactly once as a whole
/// number (not part of a longer run of digits): "run10-part3.csv" with 3 gives "run10-part" and ".csv".
std::optional<NameTemplate> nameTemplate(const std::string& path, size_t number) {
    const std::string digits = std::to_string(number);
    const size_t nameStart = path.size() - fs::path(path).filename().string().size();
    std::optional<NameTemplate> found;
    for (size_t i = nameStart; i < path.size();) {
        if (!std::isdigit(static_cast<unsigned char>(path[i]))) {
            ++i;
            continue;
        }
        size_t end = i;
        while (end < path.size() && std::isdigit(static_cast<unsigned char>(path[end]))) ++end;
        if (path.compare(i, end - i, digits) == 0 && end - i == digits.size()) {
            if (found) return std::nullopt; // twice: which one is the shard's is not known
            found = NameTemplate{path.substr(0, i), path.substr(end)};
        }
        i = end;
    }
    return found;
}

/// The shard every row of `in` belongs to; nullopt for an empty input or one of several shards.
std::optional<size_t> onlyShard(const Input& in) {
    std::optional<size_t> shard;
    for (const auto& row : in.table.rows) {
        const size_t i = parseShard(row[in.columns.shard])->index;
        if (shard && *shard != i) return std::nullopt;
        shard = i;
    }
    return shard;
}

// A shard that lacks something is rerun into its own part file: the input holding its rows, or, when
// no input does (the shard never wrote a row), the name the other part files share with the shard's
// number in it, if they all share one.
void fillPartFiles(const std::vector<Input>& inputs, std::vector<ShardGap>& gaps) {
    std::map<size_t, std::string> byShard;
    std::optional<NameTemplate> shared;
    bool oneTemplate = true;
    for (const Input& in : inputs) {
        const std::optional<size_t> shard = onlyShard(in);
        if (!shard) continue;
        byShard.emplace(*shard, in.path);
        const std::optional<NameTemplate> t = nameTemplate(in.path, *shard);
        if (!t || (shared && !(*shared == *t))) oneTemplate = false;
        if (t && !shared) shared = t;
    }
    for (ShardGap& gap : gaps) {
        if (gap.shard == 0) continue;
        const auto known = byShard.find(gap.shard);
        gap.partFileIsInput = known != byShard.end();
        if (gap.partFileIsInput)
            gap.partFile = known->second;
        else if (shared && oneTemplate)
            gap.partFile = shared->before + std::to_string(gap.shard) + shared->after;
    }
}

// ---------------------------------------------------------------------------------------------------
// Timer verdicts

/// Rows per non-empty timer_verdict, first-seen order, with where each value was first seen.
struct VerdictTally {
    std::vector<std::pair<std::string, size_t>> counts;
    std::vector<std::string> firstWhere;
};

VerdictTally tallyVerdicts(const std::vector<Input>& inputs) {
    VerdictTally tally;
    for (const Input& in : inputs) {
        auto column = std::find(in.table.header.begin(), in.table.header.end(), col::kTimerVerdict);
        if (column == in.table.header.end()) continue;
        const size_t c = size_t(column - in.table.header.begin());
        for (size_t r = 0; r < in.table.rows.size(); ++r) {
            const std::string& verdict = in.table.rows[r][c];
            if (verdict.empty()) continue; // failed rows were never measured
            auto it = std::find_if(tally.counts.begin(), tally.counts.end(),
                                   [&](const auto& entry) { return entry.first == verdict; });
            if (it != tally.counts.end()) {
                ++it->second;
                continue;
            }
            tally.counts.emplace_back(verdict, 1);
            tally.firstWhere.push_back(in.path + ":" + std::to_string(in.lines[r]));
        }
    }
    return tally;
}

void checkVerdicts(const VerdictTally& tally, const MergeOptions& options) {
    if (tally.counts.size() < 2 || options.allowMixedTimer || options.allowMixed) return;
    fail("rows measured under different GPU-timer verdicts: " + inQuotes(tally.counts[0].first) + " in " +
         inQuotes(tally.firstWhere[0]) + " but " + inQuotes(tally.counts[1].first) + " in " +
         inQuotes(tally.firstWhere[1]) +
         "; rerun the shards on one kind of machine, or pass --allow-mixed-timer (or --allow-mixed) to merge "
         "them anyway");
}

// ---------------------------------------------------------------------------------------------------
// Identity

/// The sweep_name of the first row that has one.
std::string firstSweepName(const std::vector<Input>& inputs) {
    for (const Input& in : inputs)
        if (const std::optional<size_t> c = optionalColumn(in, col::kSweepName))
            for (const auto& row : in.table.rows)
                if (!row[*c].empty()) return row[*c];
    return "";
}

/// Refuses rows of different measurements unless told to mix them; returns the mixtures it let through.
std::vector<Mixture> checkIdentity(const std::vector<Input>& inputs, const MergeOptions& options,
                                   std::optional<size_t>& hosts) {
    MeasurementIdentity identity;
    for (const Input& in : inputs) identity.add(in.table, in.path, in.lines);
    hosts = identity.hosts();
    std::vector<Mixture> mixtures = identity.mixtures();
    if (!mixtures.empty() && !options.allowMixed) fail(MeasurementIdentity::refusal(mixtures));
    return mixtures;
}

} // namespace

// Everything is read and checked before anything is written, so a refused merge leaves no trace.
MergeReport CsvMerge::merge(const std::vector<std::string>& inputs, const std::string& output,
                            const MergeOptions& options) {
    checkPaths(inputs, output, options);
    std::vector<Input> files;
    SweepCheck check;
    for (const std::string& path : inputs) {
        files.push_back(readInput(path));
        for (size_t r = 0; r < files.back().table.rows.size(); ++r) check.add(files.back(), r);
    }
    if (check.seenIndices().empty()) fail("merge: the inputs hold no rows");

    MergeReport report;
    report.files = files.size();
    report.sweepId = check.sweepId();
    report.sweepName = firstSweepName(files);
    report.configs = check.configs();
    report.shardCount = check.shardCount();
    report.missing = missingRanges(check, report.missingCount);
    const VerdictTally verdicts = tallyVerdicts(files);
    checkVerdicts(verdicts, options);
    report.timerVerdicts = verdicts.counts;
    report.mixtures = checkIdentity(files, options, report.hosts);

    const std::vector<RowPlace> places = rowPlaces(files, report.unsupportedRows);
    report.rows = places.size();
    report.failed = failedRanges(places);
    for (const auto& [first, last] : report.failed) report.failedRows += last - first + 1;
    report.incomplete = incompleteText(report);
    report.gaps = ShardGaps::compute(places, report.missing, report.configs, report.shardCount);
    fillPartFiles(files, report.gaps);
    if (!report.incomplete.empty() && !options.allowIncomplete) return report; // nothing written

    CsvWriter::writeTable(output, mergedTable(files));
    report.written = true;
    return report;
}

} // namespace sb
