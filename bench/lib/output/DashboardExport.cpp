#include "bench/lib/output/DashboardExport.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>

#include <nlohmann/json.hpp>

#include "bench/lib/output/ResultColumns.h"
#include "bench/lib/output/RowExport.h"
#include "core/Error.h"

namespace sb {

namespace {

using OrderedJson = nlohmann::ordered_json;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The exact work of a frame: identical between runs of the same build and driver (README, "the perf
// gate"), so a dashboard's chart of them moves only when the work does.
const std::vector<std::string> kCounterColumns = {col::kLoadGlCalls,    col::kLoadVertices,
                                                  col::kLoadPrimitives, col::kLoadClippedPrimitives,
                                                  col::kLoadFragments,  "ir_per_frame"};

// The unit github-action-benchmark prints beside a counter's value.
std::string counterUnit(const std::string& column) {
    if (column == "ir_per_frame") return "instructions/frame";
    return column.substr(column.find('_') + 1) + "/frame";
}

// The offset of the first byte that does not belong to a well-formed UTF-8 sequence (overlong forms,
// surrogates and code points past U+10FFFF included), npos when there is none.
size_t invalidUtf8At(const std::string& s) {
    for (size_t i = 0; i < s.size();) {
        const auto b = static_cast<unsigned char>(s[i]);
        size_t len = b < 0x80 ? 1 : (b >> 5) == 0x6 ? 2 : (b >> 4) == 0xE ? 3 : (b >> 3) == 0x1E ? 4 : 0;
        if (len == 0 || i + len > s.size()) return i;
        uint32_t cp = len == 1 ? b : len == 2 ? (b & 0x1F) : len == 3 ? (b & 0x0F) : (b & 0x07);
        for (size_t k = 1; k < len; ++k) {
            const auto c = static_cast<unsigned char>(s[i + k]);
            if ((c & 0xC0) != 0x80) return i;
            cp = (cp << 6) | (c & 0x3F);
        }
        const uint32_t least[] = {0, 0, 0x80, 0x800, 0x10000};
        if (cp < least[len] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return i;
        i += len;
    }
    return std::string::npos;
}

/// One row of a source being converted: every cell read through here is checked, and a refusal names
/// the file, the row's line and the column.
class CheckedRow {
public:
    CheckedRow(const CsvSource& source, const std::vector<std::string>& row, size_t line)
        : mSource(source), mRow(row), mLine(line) {}

    [[noreturn]] void fail(const std::string& column, const std::string& why) const {
        throw Error(mSource.name() + ":" + std::to_string(mLine) + ": column '" + column + "': " + why,
                    ExitCode::BadInput);
    }

    /// Text that goes into the JSON: refused unless valid UTF-8 (results are UTF-8; guessing Latin-1
    /// would silently change a name).
    const std::string& text(const std::string& column) const {
        const std::string& cell = mSource.cell(mRow, column);
        const size_t bad = invalidUtf8At(cell);
        if (bad != std::string::npos) {
            char hex[8];
            std::snprintf(hex, sizeof hex, "0x%02X", static_cast<unsigned char>(cell[bad]));
            fail(column, std::string("invalid UTF-8 (byte ") + hex + " at offset " + std::to_string(bad) +
                             "); result files are UTF-8");
        }
        return cell;
    }

    /// NaN for an empty cell. strtod rather than from_chars for the value: a subnormal is a valid small
    /// number, and only an overflow (HUGE_VAL with ERANGE) is out of range. The grammar check first
    /// keeps out "inf", "nan", hex and locale forms.
    double number(const std::string& column) const {
        const std::string& cell = mSource.cell(mRow, column);
        if (cell.empty()) return kNaN;
        if (!RowExport::isJsonNumberLiteral(cell)) fail(column, "'" + cell + "' is not a number");
        errno = 0;
        const double v = std::strtod(cell.c_str(), nullptr);
        if (errno == ERANGE && std::isinf(v)) fail(column, "'" + cell + "' is beyond the range of a double");
        return v;
    }

    /// A count (frames, threads, work): empty is `absent`, otherwise a whole number in [0, 2^63).
    long long count(const std::string& column, long long absent) const {
        const std::string& cell = mSource.cell(mRow, column);
        if (cell.empty()) return absent;
        long long v = 0;
        auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), v);
        if (ec == std::errc() && end == cell.data() + cell.size() && v >= 0 && cell[0] != '-') return v;
        if (ec == std::errc() && end == cell.data() + cell.size())
            fail(column, "'" + cell + "' is negative; a count is a whole number >= 0");
        fail(column, "'" + cell + "' is not a whole number from 0 to " +
                         std::to_string(std::numeric_limits<long long>::max()));
    }

private:
    const CsvSource& mSource;
    const std::vector<std::string>& mRow;
    size_t mLine;
};

// Part of a name: "" when the column is absent or empty.
void appendPart(std::string& name, const std::string& part, const std::string& prefix = "") {
    if (part.empty()) return;
    name += (name.empty() ? "" : "/") + prefix + part;
}

std::string nameOf(const CheckedRow& row) {
    const std::string& config = row.text(col::kCiConfig);
    if (!config.empty()) return config;
    std::string name = row.text(col::kTechnique);
    const std::string& properties = row.text(col::kProperties);
    if (!properties.empty()) name += ":" + properties;
    appendPart(name, row.text(col::kScene));
    appendPart(name, row.text(col::kInstances), "n");
    appendPart(name, row.text(col::kSubmit));
    appendPart(name, row.text(col::kCamera));
    const std::string &w = row.text(col::kWidth), &h = row.text(col::kHeight);
    if (!w.empty() && !h.empty()) appendPart(name, w + "x" + h);
    appendPart(name, row.text(col::kApi));
    return name;
}

// JSON has no NaN: an absent number is null.
OrderedJson jsonNumber(double v) {
    return std::isfinite(v) ? OrderedJson(v) : OrderedJson(nullptr);
}

std::string fixed(double v) {
    char text[64];
    std::snprintf(text, sizeof text, "%.4f", v);
    return text;
}

void requireTimes(const CsvSource& source) {
    if (!source.hasColumn(col::kWallMsMedian))
        throw Error("the CSV has no wall_ms_median column: not rows measured by bench (a run, a sweep, or "
                    "the perf gate's work.csv / wall.csv)",
                    ExitCode::BadInput);
}

/// `value` dumped as nlohmann's dump(2) would place it `depth` levels deep.
std::string indented(const OrderedJson& value, int depth) {
    std::string text = value.dump(2);
    const std::string pad(size_t(2 * depth), ' ');
    std::string out = pad;
    for (char c : text) {
        out += c;
        if (c == '\n') out += pad;
    }
    return out;
}

OrderedJson contextOf(const CsvSource& source, const std::vector<std::string>& first, size_t line) {
    const CheckedRow row(source, first, line);
    OrderedJson context = OrderedJson::object();
    context["date"] = row.text(col::kTimestamp);
    context["host_name"] = row.text(col::kCpuModel);
    context["executable"] = "bench";
    context["num_cpus"] = row.count(col::kHwThreads, 0);
    context["mhz_per_cpu"] = 0;
    context["cpu_scaling_enabled"] = false;
    context["caches"] = OrderedJson::array();
    context["library_build_type"] = "release";
    context[col::kRenderer] = row.text(col::kRenderer);
    context[col::kApiVersion] =
        row.text(col::kApiVersion).empty() ? row.text(col::kGlVersion) : row.text(col::kApiVersion);
    context[col::kGitCommit] = row.text(col::kGitCommit);
    return context;
}

OrderedJson benchmarkOf(const DashboardEntry& e, size_t familyIndex) {
    OrderedJson b;
    b["name"] = e.name;
    b["family_index"] = familyIndex;
    b["per_family_instance_index"] = 0;
    b["run_name"] = e.name;
    b["run_type"] = "iteration";
    b["repetitions"] = 1;
    b["repetition_index"] = 0;
    b["threads"] = 1;
    b["iterations"] = e.frames;
    b["real_time"] = jsonNumber(e.wallMs);
    b["cpu_time"] = jsonNumber(e.cpuMs);
    b["time_unit"] = "ms";
    for (const auto& [column, value] : e.counters) b[column] = value;
    return b;
}

std::vector<OrderedJson> actionItemsOf(const DashboardEntry& e) {
    std::vector<OrderedJson> items;
    if (std::isfinite(e.wallMs)) {
        OrderedJson item;
        item["name"] = e.name;
        item["unit"] = "ms";
        item["value"] = e.wallMs;
        if (std::isfinite(e.wallP5) && std::isfinite(e.wallP95))
            item["range"] = "p5-p95 " + fixed(e.wallP5) + ".." + fixed(e.wallP95);
        item["extra"] = std::to_string(e.frames) + " frames, median wall time per frame" +
                        (e.properties.empty() ? "" : "; " + e.properties);
        items.push_back(std::move(item));
    }
    for (const auto& [column, value] : e.counters) {
        OrderedJson item;
        item["name"] = e.name + " " + column;
        item["unit"] = counterUnit(column);
        item["value"] = value;
        item["extra"] = "exact work per frame (identical between runs of one build and driver)";
        items.push_back(std::move(item));
    }
    return items;
}

std::string collect(const std::function<void(const TextSink&)>& write) {
    std::string out;
    write([&](std::string_view text) { out += text; });
    return out;
}

} // namespace

std::string DashboardExport::benchmarkName(const CsvTable& table, const std::vector<std::string>& row) {
    const CsvSource source = CsvSource::table(table);
    return nameOf(CheckedRow(source, row, 0));
}

bool DashboardExport::entry(const CsvSource& source, const std::vector<std::string>& cells, size_t line,
                            DashboardEntry& e) {
    const CheckedRow row(source, cells, line);
    const std::string& status = row.text(col::kStatus);
    if (!status.empty() && status != col::kStatusOk) return false;
    e = DashboardEntry{};
    e.name = nameOf(row);
    e.status = status.empty() ? col::kStatusOk : status;
    e.properties = row.text(col::kProperties);
    e.wallMs = row.number(col::kWallMsMedian);
    e.wallP5 = row.number(col::kWallMsP5);
    e.wallP95 = row.number(col::kWallMsP95);
    e.cpuMs = row.number(col::kCpuSubmitMsMedian);
    e.frames = row.count(col::kFrames, 0);
    for (const std::string& column : kCounterColumns) {
        const double v = row.number(column);
        if (v < 0) row.fail(column, "'" + source.cell(cells, column) + "' is negative; work is counted >= 0");
        if (std::isfinite(v)) e.counters.emplace_back(column, v);
    }
    return true;
}

std::vector<DashboardEntry> DashboardExport::entries(const CsvTable& table) {
    const CsvSource source = CsvSource::table(table);
    requireTimes(source);
    std::vector<DashboardEntry> out;
    source.forEachRow([&](const std::vector<std::string>& row, size_t line) {
        DashboardEntry e;
        if (entry(source, row, line, e)) out.push_back(std::move(e));
    });
    return out;
}

std::string DashboardExport::googleBenchmark(const CsvTable& table) {
    return collect([&](const TextSink& sink) { writeGoogleBenchmark(CsvSource::table(table), sink); });
}

void DashboardExport::writeGoogleBenchmark(const CsvSource& source, const TextSink& sink) {
    requireTimes(source);
    OrderedJson context = OrderedJson::object();
    long long notOk = 0;
    bool first = true;
    source.forEachRow([&](const std::vector<std::string>& row, size_t line) {
        if (first) context = contextOf(source, row, line);
        first = false;
        DashboardEntry e;
        if (!entry(source, row, line, e)) ++notOk;
    });
    context["rows_not_ok"] = notOk;
    sink("{\n  \"context\": " + indented(context, 1).substr(2) + ",\n  \"benchmarks\": [");
    size_t written = 0;
    source.forEachRow([&](const std::vector<std::string>& row, size_t line) {
        DashboardEntry e;
        if (!entry(source, row, line, e)) return;
        sink((written ? ",\n" : "\n") + indented(benchmarkOf(e, written), 2));
        ++written;
    });
    sink(written ? "\n  ]\n}\n" : "]\n}\n");
}

std::string DashboardExport::githubActionBenchmark(const CsvTable& table) {
    return collect([&](const TextSink& sink) { writeGithubActionBenchmark(CsvSource::table(table), sink); });
}

void DashboardExport::writeGithubActionBenchmark(const CsvSource& source, const TextSink& sink) {
    requireTimes(source);
    // A check pass first, so that a bad cell stops the export before anything is written.
    source.forEachRow([&](const std::vector<std::string>& row, size_t line) {
        DashboardEntry e;
        entry(source, row, line, e);
    });
    sink("[");
    size_t written = 0;
    source.forEachRow([&](const std::vector<std::string>& row, size_t line) {
        DashboardEntry e;
        if (!entry(source, row, line, e)) return;
        for (const OrderedJson& item : actionItemsOf(e)) sink((written++ ? ",\n" : "\n") + indented(item, 1));
    });
    sink(written ? "\n]\n" : "]\n");
}

} // namespace sb
