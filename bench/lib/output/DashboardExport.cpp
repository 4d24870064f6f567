#include "bench/lib/output/DashboardExport.h"

#include <cmath>
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

double number(const CsvTable& table, const std::vector<std::string>& row, const std::string& column) {
    const std::string cell = table.cell(row, column);
    return RowExport::isNumber(cell) ? std::stod(cell) : kNaN;
}

// Part of a name: "" when the column is absent or empty.
void appendPart(std::string& name, const std::string& part, const std::string& prefix = "") {
    if (part.empty()) return;
    name += (name.empty() ? "" : "/") + prefix + part;
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

} // namespace

std::string DashboardExport::benchmarkName(const CsvTable& table, const std::vector<std::string>& row) {
    const std::string config = table.cell(row, col::kCiConfig);
    if (!config.empty()) return config;
    std::string name = table.cell(row, col::kTechnique);
    const std::string properties = table.cell(row, col::kProperties);
    if (!properties.empty()) name += ":" + properties;
    appendPart(name, table.cell(row, col::kScene));
    appendPart(name, table.cell(row, col::kInstances), "n");
    appendPart(name, table.cell(row, col::kSubmit));
    appendPart(name, table.cell(row, col::kCamera));
    const std::string w = table.cell(row, col::kWidth), h = table.cell(row, col::kHeight);
    if (!w.empty() && !h.empty()) appendPart(name, w + "x" + h);
    appendPart(name, table.cell(row, col::kApi));
    return name;
}

std::vector<DashboardEntry> DashboardExport::entries(const CsvTable& table) {
    if (!table.hasColumn(col::kWallMsMedian))
        throw Error("the CSV has no wall_ms_median column: not rows measured by bench (a run, a sweep, or "
                    "the perf gate's work.csv / wall.csv)",
                    ExitCode::BadInput);
    std::vector<DashboardEntry> out;
    for (const auto& row : table.rows) {
        const std::string status = table.cell(row, col::kStatus);
        if (!status.empty() && status != col::kStatusOk) continue;
        DashboardEntry e;
        e.name = benchmarkName(table, row);
        e.status = status.empty() ? col::kStatusOk : status;
        e.properties = table.cell(row, col::kProperties);
        e.wallMs = number(table, row, col::kWallMsMedian);
        e.wallP5 = number(table, row, col::kWallMsP5);
        e.wallP95 = number(table, row, col::kWallMsP95);
        e.cpuMs = number(table, row, col::kCpuSubmitMsMedian);
        const double frames = number(table, row, col::kFrames);
        e.frames = std::isfinite(frames) ? static_cast<long long>(frames) : 0;
        for (const std::string& column : kCounterColumns) {
            const double v = number(table, row, column);
            if (std::isfinite(v)) e.counters.emplace_back(column, v);
        }
        out.push_back(std::move(e));
    }
    return out;
}

std::string DashboardExport::googleBenchmark(const CsvTable& table) {
    const std::vector<DashboardEntry> list = entries(table);
    OrderedJson context = OrderedJson::object();
    if (!table.rows.empty()) {
        const auto& first = table.rows.front();
        context["date"] = table.cell(first, col::kTimestamp);
        context["host_name"] = table.cell(first, col::kCpuModel);
        context["executable"] = "bench";
        const double threads = number(table, first, col::kHwThreads);
        context["num_cpus"] =
            std::isfinite(threads) ? OrderedJson(static_cast<long long>(threads)) : OrderedJson(0);
        context["mhz_per_cpu"] = 0;
        context["cpu_scaling_enabled"] = false;
        context["caches"] = OrderedJson::array();
        context["library_build_type"] = "release";
        context[col::kRenderer] = table.cell(first, col::kRenderer);
        context[col::kApiVersion] = table.cell(first, col::kApiVersion).empty()
                                        ? table.cell(first, col::kGlVersion)
                                        : table.cell(first, col::kApiVersion);
        context[col::kGitCommit] = table.cell(first, col::kGitCommit);
    }
    context["rows_not_ok"] = static_cast<long long>(table.rows.size() - list.size());
    OrderedJson benchmarks = OrderedJson::array();
    for (const DashboardEntry& e : list) {
        OrderedJson b;
        b["name"] = e.name;
        b["family_index"] = benchmarks.size();
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
        benchmarks.push_back(std::move(b));
    }
    OrderedJson doc;
    doc["context"] = std::move(context);
    doc["benchmarks"] = std::move(benchmarks);
    return doc.dump(2) + "\n";
}

std::string DashboardExport::githubActionBenchmark(const CsvTable& table) {
    OrderedJson items = OrderedJson::array();
    for (const DashboardEntry& e : entries(table)) {
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
    }
    return items.dump(2) + "\n";
}

} // namespace sb
