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

AutoChoice AutoSelection::choose(EffectMask request, std::vector<AutoCandidate>& candidates,
                                 double maxWrongPct) {
    AutoChoice choice;
    size_t qualified = 0;
    for (size_t i = 0; i < candidates.size(); ++i) {
        AutoCandidate& c = candidates[i];
        c.verdict = disqualification(request, c, maxWrongPct);
        if (!c.verdict.empty()) continue;
        ++qualified;
        c.verdict = "qualifies";
        if (!choice.chosen || c.costMs < candidates[*choice.chosen].costMs) choice.chosen = i;
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
                    formatNumber("%.3g", best.wrongPct) + "% wrong)";
    return choice;
}

} // namespace sb
