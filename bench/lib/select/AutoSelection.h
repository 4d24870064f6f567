#pragma once
// `-t auto`: the cheapest technique that delivers what the scene asks for within an accuracy bound.
// The choice is a pure function of the scene's request and of each candidate's declared effects,
// measured cost and measured error (bench/lib/select/Calibration.h measures and caches those on the current
// machine), so it follows the measurements and nothing else: no technique is preferred by name, a
// candidate that lacks a requested effect or misses the bound is never chosen.
//
// Time decides only where it can: the calibration times every candidate in the same rounds,
// interleaved, so a candidate is faster than another only if it was faster in every round (with five
// rounds, a sign test at p = 1/32); medians that close in on each other under load decide nothing. The
// qualifying candidates that time cannot separate from the fastest are ranked by their error against
// the reference (equal cost, better image; not where the scene asks for no shadow), then by their
// exact work (vertex plus fragment shader invocations of one frame, which does not move with load),
// and remaining ties go to the candidate listed first (the registry's order). Candidates timed in different
// calibrations, or without rounds (a cache file written by hand), are compared by their medians.
#include <optional>
#include <string>
#include <vector>

#include "scenes/Scene.h"

namespace sb {

struct AutoCandidate {
    std::string spec;           ///< technique with its canonical properties ("shadowmap:resolution=2048:...")
    EffectMask effects = 0;     ///< TechniqueInfo::effects
    bool measured = false;      ///< false: refused on this scene and context (see `refusal`)
    std::string refusal;        ///< why it could not be measured ("" when measured)
    double costMs = 0.0;        ///< median wall time per frame of the calibration
    double wrongPct = 0.0;      ///< misclassified samples over the reference's shadowed ones (%), worst light
    std::vector<double> rounds; ///< wall time per round of an interleaved calibration (ms)
    std::string batch;          ///< the calibration the rounds belong to: rounds compare within one
    double work = -1.0;         ///< vertex + fragment shader invocations of one frame; < 0: unknown
    std::string verdict;        ///< filled by choose(): "chosen", or why not
    /// How `-t` names it where it is not the technique's defaults ("hybrid:cast=cubemap"); "" for the
    /// defaults, which are named by the technique alone.
    std::string variant;

    /// The name the candidate table, auto_choice and auto_candidates give it: `variant`, else the technique.
    std::string shownName() const { return variant.empty() ? spec.substr(0, spec.find(':')) : variant; }
};

struct AutoChoice {
    std::optional<size_t> chosen; ///< index into the candidates; empty when none qualifies
    std::string reason;           ///< one sentence: what was chosen over what, or why nothing was
};

class AutoSelection {
public:
    /// Fills each candidate's `verdict` and picks the cheapest measured candidate whose effects cover
    /// `request` and whose wrongPct is at most `maxWrongPct` (so a baseline that declares no effect
    /// qualifies only for a request of none), as the header says: by time where time separates, by
    /// accuracy and then exact work where it does not. For a request of none the bound does not apply: the
    /// error is measured against shadows the scene did not ask for.
    static AutoChoice choose(EffectMask request, std::vector<AutoCandidate>& candidates, double maxWrongPct);
    /// Whether `a` was faster than `b` in every round of one calibration (or, without comparable
    /// rounds, by its median).
    static bool faster(const AutoCandidate& a, const AutoCandidate& b);
};

} // namespace sb
