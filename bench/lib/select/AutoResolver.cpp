#include "bench/lib/select/AutoResolver.h"

#include <ostream>

#include "bench/lib/output/TextColumns.h"
#include "bench/lib/select/AutoSelection.h"
#include "bench/lib/select/Calibration.h"
#include "core/Error.h"

namespace sb {

AutoResolution AutoResolver::resolve(MeasuredHarness& harness, const RunConfig& config, std::ostream& log,
                                     const CalibrationOptions& timing) {
    CalibrationOptions options = timing;
    options.cachePath = config.calibrationPath;
    options.seedPath = config.calibrationSeedPath;
    options.refresh = config.recalibrate;
    std::vector<AutoCandidate> candidates = Calibration::candidates(harness, options, log);
    const EffectMask request = harness.scene().effects;
    const AutoChoice choice = AutoSelection::choose(request, candidates, config.autoMaxWrongPct);
    AutoResolution r;
    TextColumns table("  ");
    for (const AutoCandidate& c : candidates) {
        const std::string cost = c.measured ? formatNumber("%.3g ms", c.costMs) : "-";
        const std::string wrong = c.measured ? formatNumber("%.3g%%", c.wrongPct) : "-";
        table.addRow({c.shownName(), cost, wrong, c.verdict});
        r.candidates +=
            (r.candidates.empty() ? "" : "; ") + c.shownName() + " " + cost + " " + wrong + " " + c.verdict;
    }
    log << "auto: scene " << harness.scene().name << " asks for " << effectMaskToString(request) << "; bound "
        << formatNumber("%.3g", config.autoMaxWrongPct) << "% wrong (--auto-max-wrong)\n";
    table.print(log);
    if (!choice.chosen) throw Error("auto: " + choice.reason, ExitCode::Unsupported);
    log << "auto: chose " << choice.reason << "\n";
    r.spec = TechniqueSpec::parse(candidates[*choice.chosen].spec);
    r.chosen = candidates[*choice.chosen];
    r.reason = choice.reason;
    return r;
}

} // namespace sb
