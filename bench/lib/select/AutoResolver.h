#pragma once
// What `-t auto` becomes in a run (bench/run/RunCommand.cpp): the candidates measured or read from the
// calibration cache (Calibration), the choice (AutoSelection), both printed so the user sees what was
// weighed, and the columns that record them in the chosen technique's rows.
#include <iosfwd>
#include <string>

#include "bench/lib/harness/Harness.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/output/ResultColumns.h"
#include "bench/lib/select/AutoSelection.h"
#include "bench/lib/select/Calibration.h"
#include "techniques/PropertySet.h"

namespace sb {

struct AutoResolution {
    TechniqueSpec spec;     ///< the chosen technique with its properties
    std::string reason;     ///< AutoChoice::reason
    std::string candidates; ///< "shadowmap 3.1 ms 0.2% qualifies; planar lacks self_shadowing; ..."
    AutoCandidate chosen;   ///< the chosen candidate as calibrated (effects, cost, error)
    /// auto_choice, auto_candidates: appended to every row of the chosen technique.
    CsvRow columns() const { return {{col::kAutoChoice, reason}, {col::kAutoCandidates, candidates}}; }
};

class AutoResolver {
public:
    /// The name that asks for the choice (`-t auto`); it takes no properties.
    static constexpr const char* kName = "auto";
    /// Calibrates or reads the cache, chooses, prints the candidate table and the choice to `log`.
    /// The candidates are the forms of the harness's API, measured and judged on `harness` itself
    /// (Calibration.h). Throws Error(Unsupported) naming the request and the bound when no candidate
    /// qualifies. `timing`: the calibration's interleaved rounds and warm-up frames (the cache, seed and
    /// refresh come from `config`).
    static AutoResolution resolve(MeasuredHarness& harness, const RunConfig& config, std::ostream& log,
                                  const CalibrationOptions& timing = {});
};

} // namespace sb
