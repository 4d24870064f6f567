#pragma once
// Layer A of the perf gate (README "Gate a change"): the exact work of each configuration, compared
// exactly. The columns are the census frame's counts (bench/lib/harness/WorkCensus.h): `work_<pass>_<count>`
// per pass, the frame totals `load_*` and the techniques' own counters `counter_*`. They were
// bit-identical across runs, LP_NUM_THREADS and load on llvmpipe. Each is the application's work or the
// driver's (bench/lib/gate/WorkColumns.h), and the two are judged differently:
//
// - On one driver (the same renderer and driver version), any increase is a change of the work the
//   configuration asks for: it fails unless the same change updates the baseline (`bench ci --update`).
//   A decrease passes and is reported, so the baseline can follow it.
// - Across two drivers (a driver A/B, or a head run on another driver than the baseline) the
//   application's work must still be identical, up or down: a difference means the harness did something
//   else, and fails. The driver's work is expected to differ: it is reported with both values and their
//   ratio as an explained difference, neither a pass nor a failure.
//
// A row's driver is the "Mesa <version>" its `driver_version`, else `gl_version` (GL), else `gl_vendor`
// (Vulkan rows leave gl_version empty) names, so rows written before the driver columns existed match
// the same driver's new rows; the driver table's name ("system") is not part of it. Rows
// are matched by `ci_config` where both tables have it (the suite's names), else by the columns that
// define a configuration (technique, properties, scene, instances, scale, tessellation, seed, model,
// submit, camera, size, lights).
//
// Nothing that was not compared passes: an empty or header-only table, one without a status or any work
// column, one with no ok row, a configuration on one side only or failed on one side, a count that is not
// a whole number >= 0 (nan, negative, fractional, text; a technique's counter may have a fraction) or that
// one side has and the other lacks: each is a failure with its reason. A configuration unsupported on both
// sides is skipped (said so, not a pass).
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "bench/lib/gate/GateReport.h"
#include "bench/lib/gate/WorkColumns.h"
#include "bench/lib/output/CsvWriter.h"

namespace sb {

/// One counted quantity of one configuration that differs between base and head.
struct WorkChange {
    std::string config;
    std::string metric; ///< the column without its "work_" prefix: "depth_fragments", "load_fragments"
    double base = 0.0;
    double head = 0.0;
    WorkClass workClass = WorkClass::Application;
    bool baseAbsent = false, headAbsent = false; ///< the count is on one side only (its value reads 0)
    /// "shadowmap_fill: depth_fragments 1000 -> 1120 (+12.0%)"
    std::string describe() const;
    /// Both values and head / base: "shadowmap_vulkan: depth_fragments 59072 -> 0 (head/base 0.000)"
    std::string describeRatio() const;
};

struct WorkComparison {
    size_t configs = 0;       ///< configurations compared, on one driver or across two
    size_t acrossDrivers = 0; ///< of those, the ones whose base and head ran on different drivers
    size_t metrics = 0;       ///< counts compared over all of them
    std::vector<WorkChange> increases, decreases; ///< on one driver
    std::vector<WorkChange> applicationChanges;   ///< across drivers: the application's work differs
    std::vector<WorkChange> driverDifferences;    ///< across drivers: the driver's work differs (explained)
    std::vector<WorkChange>
        missing; ///< a count one side has and the other lacks (a pass appeared or vanished)
    std::vector<std::string> onlyInBase, onlyInHead; ///< configurations
    /// Configurations present on both sides that could not be compared, with why: no ok row on a side,
    /// rounds that disagree, a count that is not a count or is on one side only.
    std::vector<std::string> notComparable;
    std::vector<std::string> skipped;       ///< unsupported on both sides
    std::vector<std::string> problems;      ///< the whole table's: "head: the file is empty (no header)"
    std::vector<std::string> drivers;       ///< "base on ..., head on ...: 4 configurations" per driver pair
    std::map<std::string, LayerCell> cells; ///< per configuration: what happened to it

    /// Something was compared, and nothing failed (see the header comment).
    bool pass() const;
    /// The report's cell for `config`; verdict "" when the layer never saw it.
    LayerCell cell(const std::string& config) const;
};

class WorkGate {
public:
    /// True for the exact-work columns (WorkColumns::isWork).
    static bool isWorkColumn(const std::string& column) { return WorkColumns::isWork(column); }
    /// True for every column compare() reads (work columns, status, error, the key and driver columns,
    /// ci_config, renderer): a caller may drop the others before comparing.
    static bool readsColumn(const std::string& column);
    /// The key a row is matched by (see the header comment).
    static std::string configKey(const CsvTable& table, const std::vector<std::string>& row);
    /// The driver a row ran on (see the header comment), "" when the row does not say.
    static std::string driverOf(const CsvTable& table, const std::vector<std::string>& row);
    /// Compares every configuration of the two tables.
    static WorkComparison compare(const CsvTable& base, const CsvTable& head);
    /// The report's layer A: verdict (FAIL when anything failed, NO VERDICT when nothing was compared and
    /// nothing failed, else PASS) and one detail line per finding. `baseName` is "baseline" or "base".
    static GateLayer layer(const WorkComparison& w, const std::string& baseName);
};

} // namespace sb
