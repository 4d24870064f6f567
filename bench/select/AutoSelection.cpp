#include "bench/select/AutoSelection.h"

#include "bench/output/TextColumns.h"

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

/// Among the qualified candidates time cannot tell from `fastest`, the least exact work (first listed
/// on ties); `fastest` itself when any of them has no exact work to compare.
size_t breakTimeTie(const std::vector<AutoCandidate>& candidates, const std::vector<size_t>& qualified,
                    size_t fastest, std::vector<size_t>& tied) {
    for (size_t i : qualified)
        if (i == fastest || !AutoSelection::faster(candidates[fastest], candidates[i])) tied.push_back(i);
    if (tied.size() < 2) return fastest;
    for (size_t i : tied)
        if (candidates[i].work < 0.0) return fastest;
    size_t best = tied.front();
    for (size_t i : tied)
        if (candidates[i].work < candidates[best].work) best = i;
    return best;
}

std::string workText(double work) {
    return formatNumber("%.4g", work) + " shader invocations";
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
    std::vector<size_t> tied;
    std::string tie;
    if (choice.chosen) {
        const size_t fastest = *choice.chosen;
        choice.chosen = breakTimeTie(candidates, qualifiedIndices, fastest, tied);
        if (tied.size() > 1 && *choice.chosen != fastest) {
            for (size_t i : tied)
                if (i != *choice.chosen)
                    candidates[i].verdict = "qualifies; not faster in every round, more exact work (" +
                                            workText(candidates[i].work) + ")";
            tie = "; " + candidates[fastest].spec.substr(0, candidates[fastest].spec.find(':')) +
                  " was not faster in every round of the calibration, so the least exact work decided (" +
                  workText(candidates[*choice.chosen].work) + ")";
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
    choice.reason = best.spec.substr(0, best.spec.find(':')) + ": the cheapest of " +
                    std::to_string(qualified) + " candidate(s)" + bound + " (" +
                    formatNumber("%.3g", best.costMs) + " ms per frame, " +
                    formatNumber("%.3g", best.wrongPct) + "% wrong)" + tie;
    return choice;
}

} // namespace sb
