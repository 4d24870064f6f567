#pragma once
// Layer A of the perf gate (README "Gate a change"): the exact work of each configuration, compared
// exactly. The columns are the census frame's counts (bench/lib/harness/WorkCensus.h):
// `work_<pass>_<counter>` per pass, the frame totals `load_*` and the techniques' own counters `counter_*`
// (draws, triangles, texels of their maps, shadow planes ...). They were bit-identical across runs,
// LP_NUM_THREADS and load on llvmpipe, so any increase is a change of the work the configuration asks for: it
// fails unless the same change updates the baseline (`bench ci --update`). A decrease passes and is reported,
// so the baseline can follow it.
//
// Rows are matched by `ci_config` where both tables have it (the suite's names), else by the columns
// that define a configuration (technique, properties, scene, instances, scale, tessellation, seed,
// model, submit, camera, size, lights). The counts depend on the rasteriser, so rows whose `renderer`
// or `gl_version` differ are not compared (the Mesa version is part of gl_version).
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "bench/lib/output/CsvWriter.h"

namespace sb {

/// One counted quantity of one configuration that changed.
struct WorkChange {
    std::string config;
    std::string metric; ///< the column without its "work_" prefix: "depth_fragments", "load_fragments"
    double base = 0.0;  ///< absent in a table counts as 0 (a pass that appeared or vanished)
    double head = 0.0;
    /// "shadowmap_fill: depth_fragments 1000 -> 1120 (+12.0%)"
    std::string describe() const;
};

struct WorkComparison {
    size_t configs = 0; ///< configurations present in both and compared
    size_t metrics = 0; ///< counts compared over all of them
    std::vector<WorkChange> increases, decreases;
    std::vector<std::string> onlyInBase, onlyInHead; ///< configurations
    /// Configurations whose rows in one table disagree among themselves (rounds of one configuration
    /// must count the same work) or that could not be compared (renderer or Mesa differs), with why.
    std::vector<std::string> notComparable;
    /// A configuration that was measured ok in the base but failed or vanished in the head counts as
    /// a failure too: its work can no longer be checked.
    bool pass() const { return increases.empty() && onlyInBase.empty() && notComparable.empty(); }
};

class WorkGate {
public:
    /// True for the exact-work columns (work_*, load_*, counter_*, except counters that are rates).
    static bool isWorkColumn(const std::string& column);
    /// The key a row is matched by (see the header comment).
    static std::string configKey(const CsvTable& table, const std::vector<std::string>& row);
    /// Compares every configuration with status ok in both tables.
    static WorkComparison compare(const CsvTable& base, const CsvTable& head);
};

} // namespace sb
