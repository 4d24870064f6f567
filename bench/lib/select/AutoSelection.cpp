#include "bench/lib/select/AutoSelection.h"

#include "bench/lib/output/TextColumns.h"

namespace sb {

namespace {

/// Why `c` cannot be chosen, or "" when it qualifies.
std::string disqualification(EffectMask request, const AutoCandidate& c, double maxWrongPct) {
    const EffectMask missing = request & ~c.effects;
    if (missing) return "lacks " + effectMaskToString(missing);
    if (!c.measured) return "refused: " + c.refusal;
    // A scene that asks for no shadow is served by any candidate: its error against the shadowed
    // reference measures shadows nobody asked for, so the bound does not apply (the cheapest wins).
    if (!request) return "";
    if (c.wrongPct > maxWrongPct)
        return formatNumber("%.3g", c.wrongPct) + "% wrong > bound " + formatNumber("%.3g", maxWrongPct) +
               "%";
    return "";
}

} // namespace

bool AutoSelection::faster(const AutoCandidate& a, const AutoCandidate& b) {
    const bool paired =
        !a.batch.empty() && a.batch == b.batch && a.rounds.size() >= 2 && a.rounds.size() == b.rounds.size();
    if (!paired) return a.costMs < b.costMs;
    for (size_t r = 0; r < a.rounds.size(); ++r)
        if (!(a.rounds[r] < b.rounds[r])) return false;
    return true;
}

namespace {

/// Among candidates time cannot separate: fewer misplaced shadow samples first (where the scene asks for
/// shadows: equal cost, better image), then less exact work.
bool ranksBefore(const AutoCandidate& a, const AutoCandidate& b, bool judged) {
    if (judged && a.wrongPct != b.wrongPct) return a.wrongPct < b.wrongPct;
    return a.work < b.work;
}

/// The qualified candidates time cannot tell from `fastest` (into `tied`, `fastest` included) and the
/// best ranked of them (first listed on ties); `fastest` itself when one of them has no exact work.
size_t breakTimeTie(const std::vector<AutoCandidate>& candidates, const std::vector<size_t>& qualified,
                    size_t fastest, bool judged, std::vector<size_t>& tied) {
    for (size_t i : qualified)
        if (i == fastest || !AutoSelection::faster(candidates[fastest], candidates[i])) tied.push_back(i);
    if (tied.size() < 2) return fastest;
    for (size_t i : tied)
        if (candidates[i].work < 0.0) { // nothing exact to rank them by: the fastest median stays
            tied.clear();
            return fastest;
        }
    size_t best = tied.front();
    for (size_t i : tied)
        if (ranksBefore(candidates[i], candidates[best], judged)) best = i;
    return best;
}

std::string workText(double work) {
    return formatNumber("%.4g", work) + " shader invocations";
}

/// "; time could not separate volume, planar and cubemap ...: cubemap is the most accurate of them".
std::string tieText(const std::vector<AutoCandidate>& candidates, const std::vector<size_t>& tied,
                    size_t chosen, bool judged) {
    std::string names;
    for (size_t k = 0; k < tied.size(); ++k)
        names += (k == 0 ? "" : k + 1 == tied.size() ? " and " : ", ") + candidates[tied[k]].shownName();
    bool accuracyDecided = judged;
    for (size_t i : tied)
        accuracyDecided =
            accuracyDecided && (i == chosen || candidates[i].wrongPct > candidates[chosen].wrongPct);
    const AutoCandidate& c = candidates[chosen];
    return "; time could not separate " + names + " (none was faster than the others in every round of the " +
           "calibration), and " + c.shownName() +
           (accuracyDecided ? " is the most accurate of them"
            : judged        ? " does the least exact work of the most accurate (" + workText(c.work) + ")"
                            : " does the least exact work of them (" + workText(c.work) + ")");
}

} // namespace

AutoChoice AutoSelection::choose(EffectMask request, std::vector<AutoCandidate>& candidates,
                                 double maxWrongPct) {
    AutoChoice choice;
    std::vector<size_t> qualifiedIndices;
    for (size_t i = 0; i < candidates.size(); ++i) {
        AutoCandidate& c = candidates[i];
        c.verdict = disqualification(request, c, maxWrongPct);
        if (!c.verdict.empty()) continue;
        qualifiedIndices.push_back(i);
        c.verdict = "qualifies";
        if (!choice.chosen || c.costMs < candidates[*choice.chosen].costMs) choice.chosen = i;
    }
    const size_t qualified = qualifiedIndices.size();
    std::string tie;
    if (choice.chosen) {
        const size_t fastest = *choice.chosen;
        std::vector<size_t> tied;
        choice.chosen = breakTimeTie(candidates, qualifiedIndices, fastest, request != 0, tied);
        if (tied.size() > 1) {
            for (size_t i : tied)
                if (i != *choice.chosen)
                    candidates[i].verdict = "qualifies; as fast as " +
                                            candidates[*choice.chosen].shownName() +
                                            " within the rounds, ranked after it (" +
                                            formatNumber("%.3g", candidates[i].wrongPct) + "% wrong, " +
                                            workText(candidates[i].work) + ")";
            tie = tieText(candidates, tied, *choice.chosen, request != 0);
        }
    }
    const std::string wanted = effectMaskToString(request);
    if (!choice.chosen) {
        choice.reason =
            "no candidate delivers " + wanted + " within " + formatNumber("%.3g", maxWrongPct) + "% wrong";
        return choice;
    }
    AutoCandidate& best = candidates[*choice.chosen];
    best.verdict = "chosen";
    const std::string bound =
        request ? " delivering " + wanted + " within " + formatNumber("%.3g", maxWrongPct) + "% wrong"
                : " (the scene asks for no shadow: no accuracy bound)";
    choice.reason = best.shownName() + (tie.empty() ? ": the cheapest of " : ": one of the cheapest of ") +
                    std::to_string(qualified) + " candidate(s)" + bound + " (" +
                    formatNumber("%.3g", best.costMs) + " ms per frame, " +
                    formatNumber("%.3g", best.wrongPct) + "% wrong)" + tie;
    return choice;
}

} // namespace sb
