#include "bench/lib/select/AutoResolver.h"

#include <memory>
#include <ostream>

#include "bench/lib/output/TextColumns.h"
#include "bench/lib/select/AutoSelection.h"
#include "bench/lib/select/Calibration.h"
#include "core/Error.h"

namespace sb {

namespace {

/// The GL harness that judges Vulkan candidates: the same scene, camera and size; retained submission
/// (the G-buffer's: the same triangles in any mode), as bench accuracy --api vulkan's judge.
std::unique_ptr<Harness> judgeFor(const MeasuredHarness& harness, const Harness* given) {
    if (harness.api() == Api::GL || given) return nullptr;
    RunConfig gl = harness.config();
    gl.api = RunConfig::Api::GL;
    gl.submit = SubmitMode::Retained;
    gl.dumpShadersPath.clear();
    return std::make_unique<Harness>(gl);
}

} // namespace

AutoResolution AutoResolver::resolve(MeasuredHarness& harness, const RunConfig& config, std::ostream& log,
                                     Harness* judge) {
    CalibrationOptions options;
    options.cachePath = config.calibrationPath;
    options.seedPath = config.calibrationSeedPath;
    options.refresh = config.recalibrate;
    const std::unique_ptr<Harness> made = judgeFor(harness, judge);
    Harness& judging = made ? *made : judge ? *judge : static_cast<Harness&>(harness);
    std::vector<AutoCandidate> candidates = Calibration::candidates(harness, judging, options, log);
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
