#pragma once
// The wall-time gate's decision for one configuration, from head against base and from the A/A control
// (the base build against itself, measured in the same job on the same machine, interleaved the same
// way). asv-like: a FAIL needs both a large ratio and a small p, so neither a tiny-but-significant drift
// nor a large-but-noisy ratio fails a build.
//
//   threshold T = max(floor, control.ciHigh - 1)
//       the floor (5%) is the smallest slowdown worth a red build; the control's upper bootstrap bound
//       minus 1 is how large a ratio noise alone produced in this job. The A/A interval was chosen over
//       the A/A MDE because T bounds the observed ratio (what noise makes), while the MDE bounds the
//       true ratio the test can see (what power buys): using the MDE as T would demand a slowdown of
//       ~50% before failing at 9 rounds with sd 0.2.
//   unstable = control.wilcoxon.p < alpha
//       the same build differs from itself: the machine changed under the job. Nothing measured in it
//       can be trusted either way, so the verdict is INCONCLUSIVE whatever head did.
//   FAIL         head.medianRatio > 1 + T and head.wilcoxon.p < alpha (and not unstable).
//   PASS         not FAIL, and either a significant speedup (ratio < 1 - T, p < alpha) or the job could
//                have seen a slowdown of T: mdeWilcoxon(control.logSd, head.n, alpha) <= T.
//   INCONCLUSIVE otherwise: "cannot see below X%", X the MDE, infinite when n rounds cannot reach alpha.
// The MDE uses the control's sd (the noise of a ratio of two measurements of one build, which is the
// noise of head / base under H0) and the gate's exact Wilcoxon test (WallTimeStats.h).
#include <string>

#include "bench/lib/statistics/WallTimeStats.h"

namespace sb::ci {

enum class Outcome { Pass, Fail, Inconclusive };

/// "PASS", "FAIL", "INCONCLUSIVE".
const char* outcomeName(Outcome outcome);

struct WallTimeVerdict {
    Outcome outcome = Outcome::Inconclusive;
    double threshold = 0;            ///< T above, as a fraction (0.05 = 5%)
    double mde = 0;                  ///< mdeWilcoxon of the control's noise at head.n rounds (may be inf)
    bool instrumentUnstable = false; ///< the A/A control differs from 1 at alpha
    std::string reason;              ///< one line: the outcome, ratio, interval, p, threshold and MDE

    /// alpha: this configuration's share of the family-wise alpha (bonferroniAlpha or holmAlphas);
    /// floor: the smallest slowdown that may fail (fraction). alpha outside (0, 1) or floor < 0: sb::Error.
    static WallTimeVerdict decide(const WallTimeStats& head, const WallTimeStats& control, double alpha,
                                  double floor = 0.05);
};

} // namespace sb::ci
