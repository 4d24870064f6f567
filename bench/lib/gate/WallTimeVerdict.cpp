#include "bench/lib/gate/WallTimeVerdict.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/Error.h"

namespace sb::ci {

namespace {

std::string format(const char* pattern, double a, double b = 0, double c = 0, double d = 0) {
    char buffer[256];
    std::snprintf(buffer, sizeof buffer, pattern, a, b, c, d);
    return buffer;
}

std::string percent(double fraction) {
    return std::isinf(fraction) ? std::string("inf") : format("%.0f%%", 100 * fraction);
}

/// "ratio 1.08 [0.95, 1.22] p 0.3"
std::string describe(const WallTimeStats& s) {
    return format("ratio %.3f [%.3f, %.3f] p %.3g", s.medianRatio, s.ciLow, s.ciHigh, s.wilcoxon.p);
}

/// The fewest rounds whose best exact two-sided Wilcoxon p, 2^(1-n), is below alpha.
int roundsNeeded(double alpha) {
    return int(std::floor(1 - std::log2(alpha))) + 1;
}

} // namespace

const char* outcomeName(Outcome outcome) {
    switch (outcome) {
    case Outcome::Pass:
        return "PASS";
    case Outcome::Fail:
        return "FAIL";
    case Outcome::Inconclusive:
        return "INCONCLUSIVE";
    }
    return "?";
}

WallTimeVerdict WallTimeVerdict::decide(const WallTimeStats& head, const WallTimeStats& control, double alpha,
                                        double floor) {
    if (!(alpha > 0 && alpha < 1) || !(floor >= 0))
        throw Error("WallTimeVerdict: alpha must lie in (0, 1) and the floor be >= 0 (got alpha " +
                        std::to_string(alpha) + ", floor " + std::to_string(floor) + ")",
                    ExitCode::BadInput);
    WallTimeVerdict v;
    v.threshold = std::max(floor, control.ciHigh - 1);
    v.mde = mdeWilcoxon(control.logSd, head.n, alpha);
    v.instrumentUnstable = control.wilcoxon.p < alpha;
    const std::string seen = "head " + describe(head) + ", A/A " + describe(control) + ", alpha " +
                             format("%.3g", alpha) + ", threshold " + percent(v.threshold);
    const std::string power = std::isinf(v.mde) ? format("%.0f rounds cannot reach alpha (needs >= %.0f)",
                                                         double(head.n), double(roundsNeeded(alpha)))
                                                : "could detect >= " + percent(v.mde) + " here with " +
                                                      std::to_string(head.n) + " rounds";
    const bool significant = head.wilcoxon.p < alpha;
    if (v.instrumentUnstable) {
        v.outcome = Outcome::Inconclusive;
        v.reason = "INCONCLUSIVE: instrument unstable (the A/A control differs from 1 at alpha): " + seen;
    } else if (significant && head.medianRatio > 1 + v.threshold) {
        v.outcome = Outcome::Fail;
        v.reason = "FAIL: " + percent(head.medianRatio - 1) +
                   " slower, significant and beyond the threshold: " + seen;
    } else if (significant && head.medianRatio < 1 - v.threshold) {
        v.outcome = Outcome::Pass;
        v.reason = "PASS: " + percent(1 - head.medianRatio) + " faster: " + seen;
    } else if (v.mde <= v.threshold) {
        v.outcome = Outcome::Pass;
        v.reason = "PASS: no slowdown beyond the threshold, " + power + ": " + seen;
    } else {
        v.outcome = Outcome::Inconclusive;
        const std::string blind =
            std::isinf(v.mde) ? "cannot see any slowdown" : "cannot see below " + percent(v.mde);
        v.reason = "INCONCLUSIVE: " + blind + " (" + power + "): " + seen;
    }
    return v;
}

} // namespace sb::ci
