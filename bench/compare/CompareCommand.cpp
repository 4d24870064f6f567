#include "bench/compare/CompareCommand.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>

#include "bench/lib/gate/GateReport.h"
#include "bench/lib/gate/WallLayer.h"
#include "bench/lib/gate/WorkGate.h"
#include "bench/lib/options/CliParse.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/output/ResultColumns.h"
#include "bench/lib/statistics/MultipleTesting.h"
#include "bench/lib/statistics/RankTests.h"
#include "bench/lib/statistics/Statistics.h"
#include "bench/lib/statistics/WallTimeStats.h"
#include "core/Error.h"

namespace sb {

namespace {

constexpr const char* kFooter = R"(Examples:
  bench compare base.csv new.csv                        exact work per pass, and time where rounds repeat
  bench compare ci-out-old/work.csv ci-out/work.csv --json cmp.json
  bench -t shadowmap --repeat 9 --csv a.csv; ...; bench compare a.csv b.csv

Layer A compares the census columns (work_*, load_*, counter_*) exactly. On one driver any increase
fails; when the files' rows ran on two drivers (driver_version, else gl_version or gl_vendor) the
application's work (calls, draws, triangles, primitives, counters) must match exactly and the driver's
(vertex and fragment shader invocations, clipped primitives) is reported with both values. An empty or
header-only file, no ok row, a configuration in one file only or a count that is not a whole number
fails: nothing uncompared passes. Layer C
needs >= 2 rows of a configuration in both files; its rounds were measured apart, so it is a
Mann-Whitney U test on the wall medians (unpaired), failing only beyond --floor at p < alpha split
over the configurations. Instructions (layer B) and an interleaved A/A control need bench ci.)";

/// Wall medians of the ok rows, per configuration key.
std::map<std::string, std::vector<double>> roundsOf(const CsvTable& t) {
    std::map<std::string, std::vector<double>> out;
    const bool named = t.hasColumn(col::kCiConfig);
    for (const auto& row : t.rows) {
        if (t.cell(row, col::kStatus) != col::kStatusOk) continue;
        const double v = std::strtod(t.cell(row, col::kWallMsMedian).c_str(), nullptr);
        if (v > 0 && std::isfinite(v))
            out[named ? t.cell(row, col::kCiConfig) : WorkGate::configKey(t, row)].push_back(v);
    }
    return out;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return Statistics::percentileSorted(v, 0.5);
}

GateLayer compareWall(const CsvTable& base, const CsvTable& head, double familyAlpha, double floor) {
    GateLayer layer{"C: wall time (unpaired rounds)", true, false, "PASS", {}};
    const auto b = roundsOf(base), h = roundsOf(head);
    std::vector<std::string> keys;
    for (const auto& [k, v] : b)
        if (v.size() >= 2 && h.count(k) && h.at(k).size() >= 2) keys.push_back(k);
    if (keys.empty()) {
        layer.ran = false;
        layer.details.push_back("no configuration has >= 2 rounds in both files (measure with --repeat K)");
        return layer;
    }
    const double alpha = ci::bonferroniAlpha(familyAlpha, keys.size());
    bool inconclusive = false;
    for (const std::string& k : keys) {
        const ci::RankTest u = ci::mannWhitneyU(b.at(k), h.at(k));
        const double ratio = median(h.at(k)) / median(b.at(k));
        const bool fail = ratio > 1.0 + floor && u.p < alpha;
        const bool seen = u.p < alpha;
        char text[256];
        std::snprintf(text, sizeof text,
                      "%s: median ratio %.3f over %zu and %zu rounds, Mann-Whitney p=%.3g (alpha %.3g): %s",
                      k.c_str(), ratio, b.at(k).size(), h.at(k).size(), u.p, alpha,
                      fail   ? "FAIL"
                      : seen ? "PASS (significant, within the floor)"
                             : "INCONCLUSIVE");
        layer.details.push_back(text);
        if (fail) layer.verdict = "FAIL";
        inconclusive |= !seen;
    }
    if (layer.verdict != "FAIL" && inconclusive) layer.verdict = "INCONCLUSIVE";
    layer.details.push_back(
        "rounds measured apart are not interleaved and have no A/A control: a drift of the "
        "machine between the files reads as a change; bench ci measures side by side");
    return layer;
}

} // namespace

int CompareCommand::main(int argc, char** argv) {
    CLI::App app{"bench compare: the perf gate on two result files", "bench compare"};
    app.footer(kFooter);
    std::string basePath, headPath, jsonPath;
    double alpha = 0.05, floor = 0.05; // as bench ci (WallLayer.h)
    app.add_option("base", basePath, "the base's rows (CSV)")->required();
    app.add_option("new", headPath, "the new rows (CSV)")->required();
    app.add_option("--json", jsonPath, "also write the report as JSON here");
    app.add_option("--alpha", alpha, "layer C family-wise false-alarm rate")
        ->check(CLI::Range(1e-9, 0.5))
        ->capture_default_str();
    app.add_option("--floor", floor, "layer C: the smallest slowdown that may fail (fraction)")
        ->check(CLI::Range(0.0, 10.0))
        ->capture_default_str();
    if (int code = parseCli(app, argc, argv, "bench compare"); code >= 0) return code;
    WallLayer::checkThresholds(alpha, floor);
    for (const std::string& p : {basePath, headPath})
        if (!std::filesystem::exists(p)) throw Error("bench compare: " + p + ": no such file");
    // Only the columns the gate reads are kept: a million-row file of a hundred columns shrinks to them.
    const auto needed = [](const std::string& column) {
        return WorkGate::readsColumn(column) || column == col::kWallMsMedian;
    };
    const CsvTable base = CsvWriter::read(basePath, needed), head = CsvWriter::read(headPath, needed);
    if (!jsonPath.empty()) CsvWriter::checkWritable(jsonPath);

    GateReport report;
    report.title = "shadowbench compare";
    report.about = {"base: " + basePath + " (" + std::to_string(base.rows.size()) + " rows)",
                    "head (new): " + headPath + " (" + std::to_string(head.rows.size()) + " rows)"};
    report.reproduce = "bench compare " + basePath + " " + headPath;
    const WorkComparison w = WorkGate::compare(base, head);
    GateLayer a = WorkGate::layer(w, "base");
    // The table's rows: every configuration either file has, each saying what happened to it.
    for (const auto& [config, cell] : w.cells) report.rows.push_back({config, "", cell, {}, {}});
    report.layers.push_back(a);
    report.layers.push_back({"B: instructions per frame", false, false, "", {"needs bench ci (valgrind)"}});
    report.layers.push_back(compareWall(base, head, alpha, floor));
    std::cout << report.markdown();
    if (!jsonPath.empty()) CsvWriter::writeText(jsonPath, report.json().dump(2) + "\n");
    return report.failed() ? int(ExitCode::Failure) : 0;
}

} // namespace sb
