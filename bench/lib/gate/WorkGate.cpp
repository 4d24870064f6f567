#include "bench/lib/gate/WorkGate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "bench/lib/output/ResultColumns.h"

namespace sb {

namespace {

/// The columns that define a configuration when there is no ci_config (ResultRow's names).
const std::vector<std::string> kKeyColumns = {
    col::kTechnique,    col::kProperties, col::kScene,  col::kInstances, col::kScale,
    col::kTessellation, col::kTessFactor, col::kSeed,   col::kModel,     col::kSubmit,
    col::kCamera,       col::kWidth,      col::kHeight, col::kLights};

/// The counts of one configuration, with the row that carried them.
struct ConfigWork {
    std::map<std::string, double> counts; ///< column -> value (empty cells are absent)
    std::string renderer, glVersion;
    std::string disagreement; ///< non-empty when two rows of the configuration differ
};

std::map<std::string, double> countsOf(const CsvTable& t, const std::vector<std::string>& row) {
    std::map<std::string, double> out;
    for (size_t c = 0; c < t.header.size(); ++c) {
        if (!WorkGate::isWorkColumn(t.header[c]) || row[c].empty()) continue;
        char* end = nullptr;
        const double v = std::strtod(row[c].c_str(), &end);
        if (end && *end == '\0' && std::isfinite(v)) out[t.header[c]] = v;
    }
    return out;
}

std::map<std::string, ConfigWork> collect(const CsvTable& t, bool useCiConfig) {
    std::map<std::string, ConfigWork> out;
    for (const auto& row : t.rows) {
        if (t.cell(row, col::kStatus) != col::kStatusOk) continue;
        const std::string key = useCiConfig ? t.cell(row, col::kCiConfig) : WorkGate::configKey(t, row);
        auto counts = countsOf(t, row);
        auto [it, fresh] = out.try_emplace(key);
        ConfigWork& w = it->second;
        if (fresh) {
            w.counts = std::move(counts);
            w.renderer = t.cell(row, col::kRenderer);
            w.glVersion = t.cell(row, col::kGlVersion);
        } else if (w.disagreement.empty() && counts != w.counts) {
            w.disagreement = "two rows of it count different work (the counts are not exact here)";
        }
    }
    return out;
}

std::string shortMetric(const std::string& column) {
    return column.rfind("work_", 0) == 0 ? column.substr(5) : column;
}

} // namespace

std::string WorkChange::describe() const {
    char pct[32];
    if (base == 0.0)
        std::snprintf(pct, sizeof pct, "new");
    else
        std::snprintf(pct, sizeof pct, "%+.1f%%", 100.0 * (head - base) / base);
    char values[96];
    std::snprintf(values, sizeof values, "%.0f -> %.0f", base, head);
    return config + ": " + metric + " " + values + " (" + pct + ")";
}

bool WorkGate::isWorkColumn(const std::string& column) {
    // A technique counter that is a rate (the reference's rays per second) measures time, not work.
    if (column.find("per_second") != std::string::npos) return false;
    for (const char* prefix : {"work_", "load_", "counter_"})
        if (column.rfind(prefix, 0) == 0) return true;
    return false;
}

std::string WorkGate::configKey(const CsvTable& table, const std::vector<std::string>& row) {
    std::string key;
    for (const std::string& c : kKeyColumns) key += (key.empty() ? "" : " ") + c + "=" + table.cell(row, c);
    return key;
}

WorkComparison WorkGate::compare(const CsvTable& base, const CsvTable& head) {
    const bool byName = base.hasColumn(col::kCiConfig) && head.hasColumn(col::kCiConfig);
    const auto b = collect(base, byName), h = collect(head, byName);
    WorkComparison out;
    for (const auto& [key, bw] : b) {
        auto it = h.find(key);
        if (it == h.end()) {
            out.onlyInBase.push_back(key);
            continue;
        }
        const ConfigWork& hw = it->second;
        if (!bw.disagreement.empty() || !hw.disagreement.empty()) {
            out.notComparable.push_back(key + ": " + (bw.disagreement.empty() ? "head: " : "base: ") +
                                        (bw.disagreement.empty() ? hw.disagreement : bw.disagreement));
            continue;
        }
        if (bw.renderer != hw.renderer || bw.glVersion != hw.glVersion) {
            out.notComparable.push_back(key + ": measured on another rasteriser (" + bw.renderer + ", " +
                                        bw.glVersion + " against " + hw.renderer + ", " + hw.glVersion +
                                        "): exact work is compared on one driver only");
            continue;
        }
        ++out.configs;
        std::set<std::string> metrics;
        for (const auto& [m, v] : bw.counts) metrics.insert(m);
        for (const auto& [m, v] : hw.counts) metrics.insert(m);
        for (const std::string& m : metrics) {
            ++out.metrics;
            auto value = [&](const ConfigWork& w) {
                auto f = w.counts.find(m);
                return f == w.counts.end() ? 0.0 : f->second;
            };
            WorkChange change{key, shortMetric(m), value(bw), value(hw)};
            if (change.head > change.base) out.increases.push_back(change);
            if (change.head < change.base) out.decreases.push_back(change);
        }
    }
    for (const auto& [key, hw] : h)
        if (!b.count(key)) out.onlyInHead.push_back(key);
    return out;
}

} // namespace sb
