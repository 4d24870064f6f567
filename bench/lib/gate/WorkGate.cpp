#include "bench/lib/gate/WorkGate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <regex>
#include <set>

#include "bench/lib/output/ResultColumns.h"

namespace sb {

namespace {

/// The columns that define a configuration when there is no ci_config (ResultRow's names).
const std::vector<std::string> kKeyColumns = {
    col::kTechnique,  col::kProperties, col::kScene,     col::kInstances, col::kScale,  col::kTessellation,
    col::kTessFactor, col::kSeed,       col::kModel,     col::kSubmit,    col::kCamera, col::kWidth,
    col::kHeight,     col::kLights,     col::kBackFaces, col::kLighting};

/// The rows of one configuration in one table.
struct ConfigRows {
    size_t ok = 0;
    std::vector<std::string> notOk;           ///< "failed: <error>" for each row that is not ok
    std::map<std::string, std::string> cells; ///< work column -> its non-empty cell (the first ok row)
    std::string renderer, driver;             ///< of the first ok row
    std::string disagreement;                 ///< non-empty when two ok rows count different work

    bool unsupportedOnly() const {
        return ok == 0 && !notOk.empty() && std::all_of(notOk.begin(), notOk.end(), [](const std::string& s) {
                   return s.rfind(col::kStatusUnsupported, 0) == 0;
               });
    }
};

/// One table, by configuration, with what is wrong with the table as a whole.
struct Side {
    std::map<std::string, ConfigRows> configs;
    std::vector<std::string> problems;
};

std::map<std::string, std::string> workCells(const CsvTable& t, const std::vector<std::string>& row) {
    std::map<std::string, std::string> out;
    for (size_t c = 0; c < t.header.size(); ++c)
        if (WorkColumns::isWork(t.header[c]) && !row[c].empty()) out[t.header[c]] = row[c];
    return out;
}

/// The whole table's problems: each makes layer A fail, whatever its rows say.
std::vector<std::string> tableProblems(const CsvTable& t, const std::string& side) {
    if (t.header.empty()) return {side + ": the file is empty (no header)"};
    std::vector<std::string> out;
    if (!t.hasColumn(col::kStatus)) out.push_back(side + ": no status column (not a result table)");
    if (std::none_of(t.header.begin(), t.header.end(), WorkColumns::isWork))
        out.push_back(side + ": no work columns (work_*, load_*, counter_*)");
    if (t.rows.empty()) out.push_back(side + ": no rows (a header only)");
    const bool anyOk = std::any_of(t.rows.begin(), t.rows.end(), [&](const std::vector<std::string>& row) {
        return t.cell(row, col::kStatus) == col::kStatusOk;
    });
    if (!t.rows.empty() && !anyOk)
        out.push_back(side + ": none of its " + std::to_string(t.rows.size()) + " rows has status ok");
    return out;
}

Side collect(const CsvTable& t, const std::string& name, bool byName) {
    Side s;
    s.problems = tableProblems(t, name);
    for (const auto& row : t.rows) {
        const std::string key = byName ? t.cell(row, col::kCiConfig) : WorkGate::configKey(t, row);
        ConfigRows& c = s.configs[key];
        const std::string status = t.cell(row, col::kStatus);
        if (status != col::kStatusOk) {
            const std::string error = t.cell(row, col::kError);
            c.notOk.push_back((status.empty() ? "no status" : status) + (error.empty() ? "" : ": " + error));
            continue;
        }
        auto cells = workCells(t, row);
        if (++c.ok == 1) {
            c.cells = std::move(cells);
            c.renderer = t.cell(row, col::kRenderer);
            c.driver = WorkGate::driverOf(t, row);
        } else if (c.disagreement.empty() && cells != c.cells) {
            c.disagreement = "two rows of it count different work (the counts are not exact here)";
        }
    }
    return s;
}

/// The census's counts (work_*, load_*) are whole numbers >= 0 ("41"); a technique's counter is a
/// number >= 0 that may have a fraction (pcss's light_size), written with 4 decimals ("41.0000").
bool parseCount(const std::string& column, const std::string& text, double& value) {
    char* end = nullptr;
    value = std::strtod(text.c_str(), &end);
    const bool whole = value == std::floor(value) || column.rfind("counter_", 0) == 0;
    return end != text.c_str() && *end == '\0' && std::isfinite(value) && value >= 0.0 && whole;
}

/// Why a configuration present on both sides cannot be compared; "" when it can.
std::string whyNotComparable(const ConfigRows& b, const ConfigRows& h) {
    for (const auto& [side, c] : {std::pair{"base", &b}, {"head", &h}}) {
        if (c->ok == 0)
            return std::string("no ok row in the ") + side + " (" + (c->notOk.empty() ? "" : c->notOk[0]) +
                   ")";
        if (!c->disagreement.empty()) return std::string(side) + ": " + c->disagreement;
        for (const auto& [column, text] : c->cells) {
            double v = 0;
            if (!parseCount(column, text, v))
                return std::string(side) + ": " + column + " '" + text + "' is not a count (" +
                       (column.rfind("counter_", 0) == 0 ? "a number >= 0" : "a whole number >= 0") + ")";
        }
    }
    return "";
}

std::string shortMetric(const std::string& column) {
    return column.rfind("work_", 0) == 0 ? column.substr(5) : column;
}

std::string driverText(const std::string& renderer, const std::string& driver) {
    return renderer + ", " +
           (driver.empty() ? "driver unknown (no driver_version, gl_version or gl_vendor)" : driver);
}

/// `changes`' first entry without its configuration's name, and how many more there are.
std::string firstOf(const std::vector<WorkChange>& changes, bool ratio) {
    const WorkChange& c = changes.front();
    const std::string text = (ratio ? c.describeRatio() : c.describe()).substr(c.config.size() + 2);
    return text + (changes.size() > 1 ? " and " + std::to_string(changes.size() - 1) + " more" : "");
}

/// The largest relative increase first (a count that appeared counts as the largest).
void worstFirst(std::vector<WorkChange>& changes) {
    auto pct = [](const WorkChange& c) { return c.base == 0 ? 1e300 : (c.head - c.base) / c.base; };
    std::stable_sort(changes.begin(), changes.end(),
                     [&](const WorkChange& a, const WorkChange& b) { return pct(a) > pct(b); });
}

/// One configuration's counts, compared; appends to `out` and returns its cell.
LayerCell compareCounts(const std::string& key, const ConfigRows& b, const ConfigRows& h,
                        WorkComparison& out) {
    const bool sameDriver = b.renderer == h.renderer && b.driver == h.driver;
    ++out.configs;
    if (!sameDriver) ++out.acrossDrivers;
    std::set<std::string> columns;
    for (const auto& [m, v] : b.cells) columns.insert(m);
    for (const auto& [m, v] : h.cells) columns.insert(m);
    std::vector<WorkChange> up, down, app, driver, missing;
    for (const std::string& m : columns) {
        ++out.metrics;
        WorkChange c{key, shortMetric(m), 0.0, 0.0, WorkColumns::classOf(m)};
        const auto bi = b.cells.find(m), hi = h.cells.find(m);
        c.baseAbsent = bi == b.cells.end();
        c.headAbsent = hi == h.cells.end();
        if (!c.baseAbsent) parseCount(m, bi->second, c.base);
        if (!c.headAbsent) parseCount(m, hi->second, c.head);
        if (c.baseAbsent || c.headAbsent)
            missing.push_back(c);
        else if (c.base == c.head)
            continue;
        else if (!sameDriver)
            (c.workClass == WorkClass::Driver ? driver : app).push_back(c);
        else
            (c.head > c.base ? up : down).push_back(c);
    }
    for (auto [from, to] : {std::pair{&up, &out.increases},
                            {&down, &out.decreases},
                            {&app, &out.applicationChanges},
                            {&driver, &out.driverDifferences},
                            {&missing, &out.missing}})
        to->insert(to->end(), from->begin(), from->end());
    if (!missing.empty()) return {"counts on one side only: " + firstOf(missing, false), "FAIL"};
    if (!app.empty()) return {"application work differs across drivers: " + firstOf(app, false), "FAIL"};
    if (!up.empty()) {
        worstFirst(up); // the cell names the largest; the layer's details keep the columns' order
        return {firstOf(up, false), "FAIL"};
    }
    if (!sameDriver)
        return driver.empty() ? LayerCell{"exact on both drivers", "PASS"}
                              : LayerCell{"application work exact; driver work differs (explained): " +
                                              firstOf(driver, true),
                                          "EXPLAINED"};
    if (!down.empty()) return {"less work: " + firstOf(down, false), "PASS"};
    return {"exact", "PASS"};
}

/// Anything that fails layer A whatever else was compared (the header comment's list).
bool failing(const WorkComparison& w) {
    return !w.problems.empty() || !w.increases.empty() || !w.applicationChanges.empty() ||
           !w.missing.empty() || !w.onlyInBase.empty() || !w.onlyInHead.empty() || !w.notComparable.empty();
}

/// One detail line per finding, failures first, then what is reported without a verdict.
std::vector<std::string> findings(const WorkComparison& w, const std::string& baseName) {
    std::vector<std::string> out;
    auto add = [&](const std::string& prefix, const std::vector<std::string>& lines) {
        for (const std::string& l : lines) out.push_back(prefix + l);
    };
    auto addChanges = [&](const std::string& prefix, const std::vector<WorkChange>& changes, bool ratio) {
        for (const WorkChange& c : changes)
            out.push_back(prefix + (ratio ? c.describeRatio() : c.describe()));
    };
    add("unusable input: ", w.problems);
    addChanges("increase: ", w.increases, false);
    addChanges("application work differs across drivers: ", w.applicationChanges, false);
    addChanges("count on one side only: ", w.missing, false);
    for (const std::string& c : w.onlyInBase)
        out.push_back(c + ": in the " + baseName + " only (not measured now)");
    const std::string addIt = baseName == "baseline" ? " (add it with --update)" : "";
    for (const std::string& c : w.onlyInHead) out.push_back(c + ": not in the " + baseName + addIt);
    add("not compared: ", w.notComparable);
    addChanges("decrease: ", w.decreases, false);
    addChanges("driver work (explained, not judged): ", w.driverDifferences, true);
    add("skipped, unsupported on both sides: ", w.skipped);
    add("across drivers: ", w.drivers);
    return out;
}

} // namespace

std::string WorkChange::describe() const {
    char pct[32];
    if (base == 0.0 || baseAbsent)
        std::snprintf(pct, sizeof pct, "new");
    else
        std::snprintf(pct, sizeof pct, "%+.1f%%", 100.0 * (head - base) / base);
    char b[48], h[48];
    std::snprintf(b, sizeof b, "%.0f", base);
    std::snprintf(h, sizeof h, "%.0f", head);
    const std::string values = std::string(baseAbsent ? "absent" : b) + " -> " + (headAbsent ? "absent" : h);
    return config + ": " + metric + " " + values + (headAbsent ? "" : " (" + std::string(pct) + ")");
}

std::string WorkChange::describeRatio() const {
    char text[128];
    if (base == 0.0)
        std::snprintf(text, sizeof text, "%.0f -> %.0f (head/base: from 0)", base, head);
    else
        std::snprintf(text, sizeof text, "%.0f -> %.0f (head/base %.3f)", base, head, head / base);
    return config + ": " + metric + " " + text;
}

bool WorkComparison::pass() const {
    return configs > 0 && !failing(*this);
}

LayerCell WorkComparison::cell(const std::string& config) const {
    const auto it = cells.find(config);
    return it == cells.end() ? LayerCell{} : it->second;
}

std::string WorkGate::configKey(const CsvTable& table, const std::vector<std::string>& row) {
    std::string key;
    for (const std::string& c : kKeyColumns) {
        std::string value = table.cell(row, c);
        // Rows written before `--back-faces` existed drew every back face.
        if (c == col::kBackFaces && value.empty()) value = "draw";
        // Rows written before the lighting rate was a choice lit per fragment.
        if (c == col::kLighting && value.empty()) value = "fragment";
        key += (key.empty() ? "" : " ") + c + "=" + value;
    }
    return key;
}

std::string WorkGate::driverOf(const CsvTable& table, const std::vector<std::string>& row) {
    // The same driver writes its version differently per column and API ("4.5 (Compatibility Profile)
    // Mesa 22.3.6" in gl_version, "llvmpipe Mesa 25.0.7-2~bpo12+1 (LLVM 15.0.6)" in a Vulkan row's
    // gl_vendor, "Mesa 22.3.6" in driver_version), and older rows lack driver_version: the identity is
    // the "Mesa <version>" any of them names, else the first non-empty one as it is.
    static const std::regex kMesa("Mesa [0-9][^ ()]*");
    std::string first;
    for (const char* c : {col::kDriverVersion, col::kGlVersion, col::kGlVendor}) {
        const std::string text = table.cell(row, c);
        std::smatch m;
        if (std::regex_search(text, m, kMesa)) return m.str();
        if (first.empty()) first = text;
    }
    return first;
}

bool WorkGate::readsColumn(const std::string& column) {
    static const std::set<std::string> kRead = {col::kStatus,   col::kError,         col::kCiConfig,
                                                col::kRenderer, col::kDriverVersion, col::kGlVersion,
                                                col::kGlVendor};
    return isWorkColumn(column) || kRead.count(column) ||
           std::find(kKeyColumns.begin(), kKeyColumns.end(), column) != kKeyColumns.end();
}

WorkComparison WorkGate::compare(const CsvTable& base, const CsvTable& head) {
    const bool byName = base.hasColumn(col::kCiConfig) && head.hasColumn(col::kCiConfig);
    const Side b = collect(base, "base", byName), h = collect(head, "head", byName);
    WorkComparison out;
    out.problems = b.problems;
    out.problems.insert(out.problems.end(), h.problems.begin(), h.problems.end());
    std::map<std::string, size_t> pairs; // "base on X; head on Y" -> configurations
    for (const auto& [key, bc] : b.configs) {
        const auto it = h.configs.find(key);
        if (it == h.configs.end()) {
            out.onlyInBase.push_back(key);
            out.cells[key] = {"not compared: only in the base", "FAIL"};
            continue;
        }
        const ConfigRows& hc = it->second;
        if (bc.unsupportedOnly() && hc.unsupportedOnly()) {
            out.skipped.push_back(key + ": " + bc.notOk[0]);
            out.cells[key] = {"not compared: unsupported on both sides", "SKIPPED"};
            continue;
        }
        if (const std::string why = whyNotComparable(bc, hc); !why.empty()) {
            out.notComparable.push_back(key + ": " + why);
            out.cells[key] = {"not compared: " + why, "FAIL"};
            continue;
        }
        out.cells[key] = compareCounts(key, bc, hc, out);
        if (bc.renderer != hc.renderer || bc.driver != hc.driver)
            ++pairs["base on " + driverText(bc.renderer, bc.driver) + "; head on " +
                    driverText(hc.renderer, hc.driver)];
    }
    for (const auto& [key, hc] : h.configs)
        if (!b.configs.count(key)) {
            out.onlyInHead.push_back(key);
            out.cells[key] = {"not compared: not in the base", "FAIL"};
        }
    for (const auto& [text, n] : pairs)
        out.drivers.push_back(text + ": " + std::to_string(n) +
                              " configurations (application work compared exactly, driver work reported)");
    return out;
}

GateLayer WorkGate::layer(const WorkComparison& w, const std::string& baseName) {
    GateLayer layer{"A: exact work", true, false, "PASS", findings(w, baseName)};
    const bool fails = failing(w);
    if (!w.decreases.empty() && !fails && baseName == "baseline")
        layer.details.push_back("less work than the baseline: record it with bench ci --update");
    layer.details.push_back(std::to_string(w.metrics) + " counts of " + std::to_string(w.configs) +
                            " configurations compared exactly" +
                            (w.acrossDrivers ? " (" + std::to_string(w.acrossDrivers) +
                                                   " across drivers: the application's work exactly, the "
                                                   "driver's reported)"
                                             : ""));
    layer.verdict = fails ? "FAIL" : w.configs == 0 ? "NO VERDICT" : "PASS";
    if (layer.verdict == "NO VERDICT")
        layer.details.push_back("nothing was compared: no configuration is measured ok on both sides");
    return layer;
}

} // namespace sb
