#pragma once
// Result rows in the formats benchmark dashboards already read, so shadowbench's numbers (a run's rows,
// a sweep's, the perf gate's work.csv and wall.csv) can be charted by tools people run:
// - Google Benchmark's JSON (`--benchmark_format=json`: {"context", "benchmarks": [...]}), which
//   compare.py, Bencher and most CI dashboards load;
// - github-action-benchmark's "customSmallerIsBetter" input: a JSON array of {name, unit, value,
//   range, extra}, one entry per charted series.
// One row becomes one benchmark. Its name is the gate's configuration (ci_config) when the row has one,
// else technique[:properties]/scene/instances/submit/camera/WxH/api. Its time is the median wall time
// per frame (ms); the exact work of the frame (load_gl_calls, load_vertices, load_primitives,
// load_clipped_primitives, load_fragments) and instructions per frame (ir_per_frame) ride along as
// counters: these are the numbers the perf gate judges, and they do not vary between runs.
#include <string>
#include <utility>
#include <vector>

#include "bench/lib/output/CsvSource.h"
#include "bench/lib/output/CsvWriter.h"

namespace sb {

/// One benchmark: a row of a result CSV in the shape both dashboard formats need.
struct DashboardEntry {
    std::string name;
    double wallMs = 0.0;    ///< wall_ms_median (NaN when the row has none, e.g. a failed run)
    double wallP5 = 0.0;    ///< wall_ms_p5 (NaN when absent)
    double wallP95 = 0.0;   ///< wall_ms_p95 (NaN when absent)
    double cpuMs = 0.0;     ///< cpu_submit_ms_median (NaN when absent)
    long long frames = 0;   ///< measured frames (Google Benchmark's "iterations")
    std::string status;     ///< the row's status ("ok", "error", ...)
    std::string properties; ///< the technique's properties, for the extra text
    std::vector<std::pair<std::string, double>> counters; ///< exact work per frame, in column order
};

class DashboardExport {
public:
    /// One entry per row with status "ok" (failed rows have no numbers to chart; they are named in
    /// the context instead). Throws sb::Error(BadInput) when the table has no wall_ms_median column:
    /// it is not a CSV of measured rows; and, naming "<file>:<line>" and the column, for a cell it
    /// cannot convert honestly: a number that is not a JSON number literal or is beyond double range
    /// (a subnormal is a valid small number), a negative or non-integer frame count or thread count or
    /// one beyond 64 bits, a negative work counter, text that is not valid UTF-8.
    static std::vector<DashboardEntry> entries(const CsvTable& table);
    /// The entry of one row of `source` (false for a row that is not "ok"), checked as above.
    static bool entry(const CsvSource& source, const std::vector<std::string>& row, size_t line,
                      DashboardEntry& out);
    /// The benchmark's name for a row (see the file comment).
    static std::string benchmarkName(const CsvTable& table, const std::vector<std::string>& row);

    /// Google Benchmark JSON: "context" from the first row (date, host CPU, threads, library build
    /// type, the renderer and commit as extra keys), "benchmarks" one per entry with run_type
    /// "iteration", iterations = frames, real_time = wall median, cpu_time = CPU submit median,
    /// time_unit "ms", and the counters as extra numeric fields. Ends in a newline.
    static std::string googleBenchmark(const CsvTable& table);
    /// The same streamed: a first pass checks every row and counts those not ok (the context comes
    /// first), the second writes one benchmark at a time.
    static void writeGoogleBenchmark(const CsvSource& source, const TextSink& sink);

    /// github-action-benchmark customSmallerIsBetter: per entry one item "<name>" in ms with range
    /// "p5-p95 a..b" and, per counter, one item "<name> <counter>" with the counter's unit. Ends in a
    /// newline.
    static std::string githubActionBenchmark(const CsvTable& table);
    /// The same streamed (one pass; a bad cell stops it before the rest is written).
    static void writeGithubActionBenchmark(const CsvSource& source, const TextSink& sink);
};

} // namespace sb
