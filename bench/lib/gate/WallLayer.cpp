#include "bench/lib/gate/WallLayer.h"

#include <cmath>
#include <cstdio>
#include <map>

#include "bench/lib/gate/WallTimeVerdict.h"
#include "bench/lib/output/ProgressBar.h"
#include "bench/lib/output/ResultColumns.h"
#include "bench/lib/statistics/MultipleTesting.h"
#include "bench/lib/statistics/WallTimeStats.h"
#include "core/Error.h"

namespace sb {

namespace {

double wallOf(const CsvRow& row) {
    for (const auto& [k, v] : row)
        if (k == col::kWallMsMedian) return std::strtod(v.c_str(), nullptr);
    throw Error("a run's row has no wall_ms_median", ExitCode::Failure);
}

std::string percent(double fraction) {
    if (!std::isfinite(fraction)) return "any";
    char b[32];
    std::snprintf(b, sizeof b, "%.0f%%", 100.0 * fraction);
    return b;
}

std::string statsText(const ci::WallTimeStats& s) {
    char b[128];
    std::snprintf(b, sizeof b, "%.3f [%.3f, %.3f] p=%.3g", s.medianRatio, s.ciLow, s.ciHigh, s.wilcoxon.p);
    return b;
}

/// Base and head series of one configuration (one value per round).
struct Series {
    std::vector<double> base, head;
};

} // namespace

void WallLayer::checkThresholds(double familyAlpha, double floor) {
    auto check = [](const char* option, double v, double lo, double hi) {
        if (!std::isfinite(v) || v < lo || v > hi) {
            char text[160];
            std::snprintf(text, sizeof text, "%s %g: expected a number in [%g, %g]", option, v, lo, hi);
            throw Error(text, ExitCode::BadInput);
        }
    };
    check("--alpha", familyAlpha, 1e-9, 0.5);
    check("--floor", floor, 0.0, 10.0);
}

WallLayerResult WallLayer::run(const CiSuite& suite, const std::vector<const CiConfig*>& configs,
                               const std::optional<CiSide>& base, const CiSide& head,
                               const WallLayerOptions& options) {
    WallLayerResult out;
    out.layer.name = "C: wall time";
    out.layer.ran = true;
    const CiSide& reference = base ? *base : head; // the A/A control's side
    const CiConfig& control =
        suite.config(suite.wall.control.empty() ? configs.front()->name : suite.wall.control);
    const CiRunRequest request{suite.wall.frames, suite.wall.warmup, {}, {}};
    const std::vector<ci::Order> order = ci::interleave(options.rounds, options.seed, options.scheme);
    std::map<std::string, Series> series;
    Series controlSeries;
    // Each round: every configuration twice (a pair), and the control's pair when there is a base.
    ProgressBar bar(stderr, size_t(options.rounds) * (configs.size() + (base ? 1 : 0)) * 2, 0);
    auto measure = [&](const CiConfig& c, const CiSide& side, int round, const char* role) {
        CsvRow row = bar.step("wall time round " + std::to_string(round + 1) + "/" +
                                  std::to_string(options.rounds) + " " + c.name + " (" + role + ")",
                              [&] { return SuiteRunner::run(suite, c, side, request); });
        row.insert(row.begin() + 2, {col::kCiRound, std::to_string(round)});
        row.insert(row.begin() + 3, {col::kCiRole, role});
        const double wall = wallOf(row);
        out.runs.push_back(std::move(row));
        return wall;
    };
    for (int r = 0; r < options.rounds; ++r) {
        const bool baseFirst = order[size_t(r)] == ci::Order::BaseFirst;
        for (const CiConfig* c : configs) {
            Series& s = series[c->name];
            // Without a base the configuration's own A/A pair is what is measured: two head runs.
            const CiSide& first = baseFirst ? reference : head;
            const CiSide& second = baseFirst ? head : reference;
            const double a = measure(*c, first, r, baseFirst ? "base" : "head");
            const double b = measure(*c, second, r, baseFirst ? "head" : "base");
            s.base.push_back(baseFirst ? a : b);
            s.head.push_back(baseFirst ? b : a);
        }
        if (base) {
            controlSeries.base.push_back(measure(control, reference, r, "control_a"));
            controlSeries.head.push_back(measure(control, reference, r, "control_b"));
        }
    }
    bar.close();
    if (!base) controlSeries = series[control.name];
    const ci::WallTimeStats controlStats = ci::WallTimeStats::compute(controlSeries.base, controlSeries.head);
    const double alpha = ci::bonferroniAlpha(options.familyAlpha, configs.size());
    const double mde = ci::mdeWilcoxon(controlStats.logSd, size_t(options.rounds), alpha);
    out.layer.details.push_back("A/A control (" + control.name + ", " + reference.describe() +
                                " against itself): " + statsText(controlStats) + ", sd of the log ratio " +
                                std::to_string(controlStats.logSd).substr(0, 5));
    out.layer.details.push_back("with " + std::to_string(options.rounds) + " rounds, alpha " +
                                std::to_string(alpha).substr(0, 7) + " per configuration (family " +
                                std::to_string(options.familyAlpha).substr(0, 6) + " over " +
                                std::to_string(configs.size()) + "): could detect >= " + percent(mde) +
                                " here; a FAIL needs both the ratio beyond max(" + percent(options.floor) +
                                ", the control's upper bound) and p < alpha");
    bool failed = false, inconclusive = false;
    for (const CiConfig* c : configs) {
        const Series& s = series[c->name];
        const ci::WallTimeStats stats = ci::WallTimeStats::compute(s.base, s.head);
        LayerCell cell;
        cell.summary = statsText(stats);
        if (!base) {
            // The same build against itself: informative only (what this job could see).
            cell.verdict = stats.wilcoxon.p < alpha ? "INCONCLUSIVE" : "PASS";
            cell.summary = "A/A " + cell.summary;
            inconclusive |= stats.wilcoxon.p < alpha;
        } else {
            const ci::WallTimeVerdict v =
                ci::WallTimeVerdict::decide(stats, controlStats, alpha, options.floor);
            cell.verdict = ci::outcomeName(v.outcome);
            failed |= v.outcome == ci::Outcome::Fail;
            inconclusive |= v.outcome == ci::Outcome::Inconclusive;
            out.layer.details.push_back(c->name + ": " + v.reason);
        }
        out.cells.emplace_back(c->name, cell);
    }
    if (!base)
        out.layer.details.push_back("no base given (--base-bench, --base-env): only the head against itself, "
                                    "which shows the noise, not a change");
    out.layer.verdict = failed ? "FAIL" : inconclusive ? "INCONCLUSIVE" : "PASS";
    return out;
}

} // namespace sb
