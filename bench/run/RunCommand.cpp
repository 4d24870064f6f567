#include "bench/run/RunCommand.h"

#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "bench/lib/harness/Harness.h"
#include "bench/lib/harness/VulkanHarness.h"
#include "bench/lib/images/AccuracyImages.h"
#include "bench/lib/images/RunImageNames.h"
#include "bench/lib/measure/AccuracyEvaluator.h"
#include "bench/lib/measure/Measurement.h"
#include "bench/lib/options/QualitySweep.h"
#include "bench/lib/options/RunOptions.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/output/ImageWriter.h"
#include "bench/lib/output/ResultColumns.h"
#include "bench/lib/output/RowExport.h"
#include "bench/lib/output/StandardStreams.h"
#include "bench/lib/rows/Environment.h"
#include "bench/lib/rows/ResultRow.h"
#include "bench/lib/rows/SamplesFile.h"
#include "bench/lib/rows/TraceWriter.h"
#include "bench/lib/select/AutoResolver.h"
#include "bench/lib/viewer/Viewer.h"
#include "bench/run/ConsoleReport.h"
#include "core/Error.h"
#include "registry/TechniqueRegistry.h"
#include "shading/ShaderLimits.h"
#include "techniques/EffectCoverage.h"

namespace sb {

namespace {
/// --screenshot and --visibility of the frame just measured (the census frame, which writes the visibility
/// target), on either API, under the configuration's `label` (RunImageNames.h: every configuration keeps
/// its own files). Returns the columns that record them in the row.
CsvRow writeImages(const RunConfig& config, MeasuredHarness& harness, const std::string& label) {
    CsvRow recorded;
    if (!config.screenshotPath.empty()) {
        const std::string path = RunImageNames::withLabel(config.screenshotPath, label);
        ImageWriter::writeColor(harness.width(), harness.height(), harness.readColor(), path);
        recorded.emplace_back(col::kScreenshotFile, RunImageNames::recorded(path, config.csvPath));
    }
    if (!config.visibilityPath.empty()) {
        const std::string base = RunImageNames::withLabel(config.visibilityPath, label);
        const std::vector<float> vis = harness.readVisibility();
        const size_t lights =
            std::max<size_t>(1, std::min<size_t>(harness.scene().lights.size(), kMaxLights));
        for (size_t i = 0; i < lights; ++i)
            ImageWriter::writeVisibility(harness.width(), harness.height(), vis, int(i),
                                         RunImageNames::lightFile(base, i));
        recorded.emplace_back(col::kVisibilityFile, RunImageNames::recorded(base, config.csvPath));
    }
    return recorded;
}
/// Every output is checked before the first frame, so a path that cannot be written fails in
/// milliseconds instead of after minutes of measuring with the CSV row already appended.
void checkOutputs(const RunConfig& config) {
    if (!config.csvPath.empty()) CsvWriter::checkWritable(config.csvPath);
    if (!config.samplesPath.empty()) CsvWriter::checkWritable(config.samplesPath);
    if (!config.tracePath.empty()) TraceWriter::checkWritable(config.tracePath);
    if (!config.screenshotPath.empty()) ImageWriter::checkWritable(config.screenshotPath, "--screenshot");
    if (!config.visibilityPath.empty()) ImageWriter::checkWritable(config.visibilityPath, "--visibility");
    if (config.format != RowFormat::Console) StandardStreams::requireStdout("--format");
}

/// --trace: every measured run's frames, written once after the last (nothing during the frames).
void writeTrace(const RunConfig& config, const std::vector<Measurement>& results) {
    if (config.tracePath.empty()) return;
    TraceWriter trace;
    for (const Measurement& m : results) trace.addRun(m.run, m.row);
    trace.write(config.tracePath);
}

/// bench accuracy --images: the pictures of the frame `evaluator` has just scored, as configuration
/// `label` (only the first round's: a later round of the same configuration would replace them).
void drawImages(AccuracyImages* images, const AccuracyEvaluator* evaluator, const Measurement& m,
                const std::string& label, EffectMask effects, int round, const RunConfig& config,
                std::ostream& log) {
    if (!images || !evaluator || !m.accuracy || round != 1 || !evaluator->lastJudged()) return;
    const AccuracyEvaluator::Sample& s = *evaluator->lastJudged();
    const std::vector<std::string> written =
        images->add(label, s.technique, s.reference, s.mask, m.accuracy->hard, m.accuracy->soft,
                    hasEffect(effects, Effect::SoftShadows), m.accuracy->softReference);
    if (config.quiet) return;
    log << "  images:";
    for (const std::string& path : written) log << " " << path;
    log << "\n";
}

/// The contact sheet once every configuration is drawn.
void finishImages(const AccuracyImages* images, const RunConfig& config, std::ostream& log) {
    if (!images) return;
    const std::string sheet = images->writeContactSheet();
    if (!sheet.empty() && !config.quiet) log << "contact sheet: " << sheet << "\n";
}

/// Progress and tables go to stdout, unless stdout carries the rows in a machine format (--format).
std::ostream& logStream(const RunConfig& config) {
    return config.format == RowFormat::Console ? std::cout : std::cerr;
}

/// A technique that could not be measured (it refused the configuration in setScene or compile, the
/// context lacks what it needs, or a frame failed): its row, exit code and message.
struct Refusal {
    CsvRow row;
    ExitCode code = ExitCode::Failure;
    std::string what;    ///< the error's own line
    std::string message; ///< prefixed with the technique when the line does not name it
};

/// A sweep's words for the same: the context could not (exit code 3), or the technique failed.
const char* statusOf(ExitCode code) {
    return code == ExitCode::Unsupported ? col::kStatusUnsupported : col::kStatusFailed;
}

/// The row of a technique that threw `e`: what it is and why it has no numbers, in the columns a sweep
/// uses for the same (`status`, `error`).
Refusal refusal(const std::string& technique, const std::string& properties, const Error& e,
                const Environment& env, int round, const std::string& baseline,
                const EffectCoverage& coverage) {
    Refusal r;
    r.code = e.code();
    r.what = e.what();
    r.message = r.what.rfind(technique + ":", 0) == 0 ? r.what : technique + ": " + r.what;
    r.row = {{col::kTimestamp, Environment::nowIso8601()},
             {col::kGitCommit, env.gitCommit},
             {col::kStatus, statusOf(e.code())},
             {col::kError, r.what},
             {col::kTechnique, technique},
             {col::kProperties, properties},
             {col::kRepeat, std::to_string(round)},
             {col::kBaseline, baseline}};
    for (auto& column : env.placeColumns()) r.row.push_back(std::move(column));
    for (auto& column : ResultRow::effectColumns(coverage)) r.row.push_back(std::move(column));
    return r;
}

/// A technique short of an effect the scene asks for, without --strict-effects: one line on stderr,
/// once per run (not per round), before its progress line; the run goes on (the user may want to
/// measure it anyway).
void warnEffects(const RunConfig& config, const Technique& technique, const EffectCoverage& coverage,
                 const std::string& scene, int round) {
    if (!coverage.fallsShort() || config.strictEffects || round != 1) return;
    std::cerr << "bench: warning: " << coverage.shortfall(technique.name(), scene)
              << "; measured anyway (--strict-effects refuses it)\n";
}

/// With --strict-effects the same shortfall is a refusal: exit 3, the technique cannot deliver what the
/// scene needs, as with a missing extension.
void requireEffects(const RunConfig& config, const Technique& technique, const EffectCoverage& coverage,
                    const std::string& scene) {
    if (config.strictEffects && coverage.fallsShort())
        throw Error(coverage.shortfall(technique.name(), scene) + " (--strict-effects)",
                    ExitCode::Unsupported);
}

bool isAuto(const TechniqueSpec& spec) {
    if (spec.name != AutoResolver::kName) return false;
    if (!spec.properties.empty())
        throw Error("-t auto takes no properties (it chooses a technique with its defaults; bound it with "
                    "--auto-max-wrong)");
    return true;
}

/// The worst of the refusals: a failed run (1) over bad input (2) over what the context lacks (3).
const Refusal& worst(const std::vector<Refusal>& refusals) {
    const Refusal* w = &refusals.front();
    for (const Refusal& r : refusals)
        if (worseExitCode(w->code, r.code) != w->code) w = &r;
    return *w;
}

/// Appends the last `unwritten` refusal rows to the CSV (if any is asked for).
void appendRefusals(const RunConfig& config, const std::vector<Refusal>& refusals, size_t& unwritten) {
    if (!config.csvPath.empty() && unwritten > 0) {
        std::vector<CsvRow> rows;
        for (size_t k = refusals.size() - unwritten; k < refusals.size(); ++k)
            rows.push_back(refusals[k].row);
        CsvWriter::appendRows(config.csvPath, rows);
    }
    unwritten = 0;
}

/// The end of a run: the console table (and, with several rounds, the paired ratios), or the rows in
/// the format --format asked for; then each refusal on stderr.
void report(const RunConfig& config, const MeasuredHarness& harness, const std::vector<Measurement>& results,
            const std::vector<Refusal>& refusals) {
    std::ostream& log = logStream(config);
    std::vector<RunResult> runs;
    std::vector<CsvRow> rows;
    for (const Measurement& m : results) {
        runs.push_back(m.run);
        rows.push_back(m.row);
    }
    for (const Refusal& r : refusals) rows.push_back(r.row);
    if (config.mode == RunConfig::Mode::Accuracy) {
        std::vector<std::pair<RunResult, AccuracyResult>> judged;
        for (const Measurement& m : results) judged.emplace_back(m.run, *m.accuracy);
        ConsoleReport::printAccuracyTable(log, judged);
    } else {
        ConsoleReport::printTable(log, harness, runs, config.repeat);
    }
    if (config.repeat > 1) ConsoleReport::printPairedRatios(log, runs, config.repeat);
    if (!config.csvPath.empty() && !config.quiet) log << "rows appended to " << config.csvPath << "\n";
    if (config.format != RowFormat::Console) {
        std::cout << RowExport::format(CsvWriter::toTable(rows), config.format);
        StandardStreams::finishStdout("--format");
    }
    for (const Refusal& r : refusals)
        std::cerr << "bench: error: " << r.message << " (exit code " << int(r.code) << ")\n";
}

} // namespace

std::vector<TechniqueSpec> RunCommand::configurations(const RunConfig& config) {
    std::vector<TechniqueSpec> specs;
    for (const TechniqueSpec& spec : config.techniques) {
        auto expanded = config.sweep ? QualitySweep::expand(spec) : std::vector<TechniqueSpec>{spec};
        specs.insert(specs.end(), expanded.begin(), expanded.end());
    }
    return specs;
}

namespace {
int runMeasured(const RunConfig& config, const std::string& imagesDir);
} // namespace

int RunCommand::run(const RunConfig& config) {
    return runMeasured(config, "");
}

namespace {

/// The techniques of a run on its API, created before anything else so that a typo fails in milliseconds.
/// A configuration whose technique has no form on the API is not an error of the run: it becomes a
/// refusal (a row, exit 3 at the end) while the others are measured, as any other refusal does.
struct Configured {
    TechniqueSpec spec;
    std::unique_ptr<Technique> technique; ///< null: `-t auto` (resolved later) or refused
    std::optional<Error> refused;         ///< why there is no technique on this API
};

std::vector<Configured> createTechniques(const RunConfig& config, const std::vector<TechniqueSpec>& specs) {
    const Api api = config.api == RunConfig::Api::Vulkan ? Api::Vulkan : Api::GL;
    std::vector<Configured> out;
    for (const TechniqueSpec& spec : specs) {
        Configured c{spec, nullptr, std::nullopt};
        if (!isAuto(spec)) { // -t auto is resolved on the run's harness, on its API
            try {
                c.technique = TechniqueRegistry::create(spec, api);
            } catch (const Error& e) {
                if (e.code() != ExitCode::Unsupported) throw; // bad input fails before anything runs
                c.refused = e;
            }
        }
        out.push_back(std::move(c));
    }
    return out;
}

/// The harness of the run's API. It judges its own frames too (accuracy renders its G-buffer on the
/// same API): a Vulkan run creates no GL context.
std::unique_ptr<MeasuredHarness> createHarness(const RunConfig& config) {
    if (config.api != RunConfig::Api::Vulkan) return std::make_unique<Harness>(config);
    if (config.context.visibleWindow)
        throw Error("--window draws with GL; --api vulkan measures headless only", ExitCode::Unsupported);
    return std::make_unique<VulkanHarness>(config);
}

/// The label each configuration's --screenshot and --visibility files get (RunImageNames.h), from the
/// techniques as they run (`-t auto` already resolved); a refused one is named by its spec.
std::vector<std::string> imageLabels(const std::vector<Configured>& configured) {
    std::vector<RunImageNames::Configuration> run;
    for (const Configured& c : configured)
        run.push_back({c.spec.name, c.technique ? c.technique->properties()
                                                : TechniqueRegistry::describe(c.spec)->properties()});
    return RunImageNames::labels(run);
}

/// RunCommand::run, with bench accuracy's pictures written into `imagesDir` when it is not empty: the one
/// run loop of every API (bench/lib/harness/MeasuredHarness.h).
int runMeasured(const RunConfig& config, const std::string& imagesDir) {
    // Declared before the techniques so that it is destroyed after them: techniques release API objects
    // in their destructors, which needs the harness's context or device (also when an exception unwinds).
    std::unique_ptr<MeasuredHarness> harnessOwner;
    const bool accuracy = config.mode == RunConfig::Mode::Accuracy;
    // Validate everything that needs no context first: a typo fails in milliseconds, not after a run.
    std::vector<TechniqueSpec> specs = RunCommand::configurations(config);
    std::vector<Configured> configured = createTechniques(config, specs);
    checkOutputs(config);
    if (!imagesDir.empty()) AccuracyImages::prepareDirectory(imagesDir);

    harnessOwner = createHarness(config);
    MeasuredHarness& harness = *harnessOwner;
    // `-t auto` becomes the technique the calibration chooses, with the choice recorded in its rows (either
    // API).
    std::vector<CsvRow> autoColumns(configured.size());
    for (size_t i = 0; i < configured.size(); ++i) {
        if (configured[i].technique || configured[i].refused) continue;
        const AutoResolution chosen = AutoResolver::resolve(harness, config, logStream(config));
        configured[i].spec = specs[i] = chosen.spec;
        configured[i].technique = TechniqueRegistry::create(chosen.spec, harness.api());
        autoColumns[i] = chosen.columns();
    }
    const std::vector<std::string> labels = imageLabels(configured);
    if (!accuracy && harness.api() == Api::GL && config.context.backend == Backend::Glfw &&
        config.context.visibleWindow) {
        std::vector<std::unique_ptr<GlTechnique>> techniques;
        for (Configured& c : configured)
            if (c.technique) techniques.emplace_back(static_cast<GlTechnique*>(c.technique.release()));
        Harness& gl = static_cast<Harness&>(harness);
        int code = Viewer::run(gl, techniques, config.windowFrames);
        // The last frame shown, when asked for (the viewer draws with the same targets).
        if (!config.screenshotPath.empty()) ImageWriter::writeColor(gl.targets(), config.screenshotPath);
        return code;
    }
    std::ostream& log = logStream(config);
    if (!config.quiet) ConsoleReport::printHeader(log, harness);
    if (config.checkTimer) harness.calibrateTimer();
    if (!config.quiet) ConsoleReport::printTimerVerdict(log, harness.timerVerdict());
    std::unique_ptr<AccuracyEvaluator> evaluator;
    if (accuracy) evaluator = std::make_unique<AccuracyEvaluator>(harness);
    AccuracyOptions options;
    options.light = config.accuracyLight;
    options.referenceSamples = config.referenceSamples;
    options.stability = config.stability;
    std::unique_ptr<AccuracyImages> images;
    if (evaluator && !imagesDir.empty())
        images = std::make_unique<AccuracyImages>(imagesDir, harness.scene().name, config.accuracyLight,
                                                  config.width, config.height);

    Environment env = Environment::capture();
    std::vector<Measurement> results;
    std::vector<Refusal> refusals;
    std::vector<bool> refused(configured.size(), false);
    size_t unwritten = 0; // refusal rows not in the CSV yet: held until a technique has been measured
    const std::string baseline = specs.front().toString();
    const size_t total = specs.size() * size_t(config.repeat);
    size_t done = 0;
    auto refuse = [&](size_t i, const std::string& name, const std::string& properties, const Error& e,
                      const EffectCoverage& coverage, int round) {
        // One technique's refusal (an open mesh it was told to refuse, a light type or an extension it
        // lacks, no form on this API) must not cost the others their measurement: reported as a row,
        // and the exit code says so at the end. The harness resets the frame state every frame, so the
        // next technique starts clean.
        refusals.push_back(refusal(name, properties, e, env, round, baseline, coverage));
        refused[i] = true;
        ++unwritten;
        if (!config.quiet) log << " " << statusOf(e.code()) << ": " << e.what() << "\n";
        if (!results.empty()) appendRefusals(config, refusals, unwritten);
    };
    // Rounds interleave the techniques (A B C, A B C ...): ratios are taken within a round, between
    // runs measured next to each other.
    for (int round = 1; round <= config.repeat; ++round) {
        std::optional<double> baselineWall;
        for (size_t i = 0; i < configured.size(); ++i) {
            ++done;
            // A refusal repeats every round (the same scene, properties and context): reported once.
            if (refused[i]) continue;
            if (!configured[i].technique) {
                if (!config.quiet)
                    log << "[" << done << "/" << total << "] " << specs[i].toString() << " ...";
                refuse(i, specs[i].name, TechniqueRegistry::describe(specs[i])->properties().toString(),
                       *configured[i].refused, EffectCoverage::of(harness.scene().effects, 0), round);
                continue;
            }
            Technique& technique = *configured[i].technique;
            const EffectCoverage coverage =
                EffectCoverage::of(harness.scene().effects, technique.info().effects);
            warnEffects(config, technique, coverage, harness.scene().name, round);
            if (!config.quiet)
                log << "[" << done << "/" << total << "] " << technique.name() << " "
                    << technique.properties().toString() << " ..." << std::flush;
            std::optional<Measurement> measured;
            try {
                requireEffects(config, technique, coverage, harness.scene().name);
                measured = Measurement::take(harness, technique, evaluator.get(), options, env);
            } catch (const Error& e) {
                refuse(i, technique.name(), technique.properties().toString(), e, coverage, round);
                continue;
            }
            appendRefusals(config, refusals, unwritten); // the ones before the first measurement
            Measurement& m = *measured;
            for (const auto& column : autoColumns[i]) m.row.push_back(column);
            if (i == 0) baselineWall = m.run.wall.median;
            m.addRound(round, baseline, baselineWall);
            for (const std::string& message : harness.takeValidationMessages())
                std::cerr << "bench: " << apiName(harness.api()) << " validation: " << message << "\n";
            if (!config.quiet) {
                log << " " << m.run.wall.n << " frames, median " << m.run.wall.median << " ms";
                if (m.accuracy) log << ", " << m.accuracy->hard.wrongPct << "% wrong";
                log << "\n";
            }
            // The pictures before the row, so that a row never names a file that was not written.
            for (auto& column : writeImages(config, harness, labels[i])) m.row.push_back(std::move(column));
            if (!config.csvPath.empty()) CsvWriter::appendRows(config.csvPath, {m.row});
            if (!config.samplesPath.empty()) SamplesFile::append(config.samplesPath, harness, m.run);
            drawImages(images.get(), evaluator.get(), m, specs[i].toString(), technique.info().effects, round,
                       config, log);
            results.push_back(std::move(m));
        }
    }
    // Nothing measured: the run failed as a whole, with the worst error's own line and code, as a
    // single technique always did (and an existing CSV is left as it was).
    if (results.empty() && !refusals.empty()) throw Error(worst(refusals).what, worst(refusals).code);
    finishImages(images.get(), config, log);
    writeTrace(config, results);
    report(config, harness, results, refusals);
    // With validation (--vk-validation) a run the layer found fault with did not render what the API
    // promises: it failed, whatever its numbers.
    if (const size_t errors = harness.validationErrors()) {
        std::cerr << "bench: error: the " << apiName(harness.api()) << " validation layer reported " << errors
                  << " error(s) (above); the run is not valid (exit code 1)\n";
        return int(ExitCode::Failure);
    }
    return refusals.empty() ? 0 : int(worst(refusals).code);
}
} // namespace

namespace {
// `bench accuracy --help`'s end: what it measures, the columns it adds, examples.
constexpr const char* kAccuracyFooter =
    R"(Each technique renders one frame; its visibility of the judged light is compared pixel by pixel
with Embree's exact answer at the same pixels (bench --help: every other option). Columns added to
the row (README, "CSV columns"): acc_wrong_pct (pixels on the wrong side of the shadow edge),
acc_wrong_no_edge_pct (the same outside the edge band), acc_rmse (soft shadows), acc_nan, acc_inf,
acc_out_of_range (numeric sanity), acc_gain_camera, acc_gain_light, acc_flicker (stability under
small perturbations; --no-stability skips them).

Examples:
  bench accuracy -t shadowmap -t volume                  both against the reference, aircraft x200
  bench accuracy -t shadowmap --sweep --csv acc.csv      error against time for every shadowmap knob
  bench accuracy -t pcss -t vsm --ref-samples 64        soft shadows against a 64-sample area light
  bench accuracy --api vulkan -t shadowmap               the Vulkan frame judged the same way
  bench accuracy -t shadowmap -t pcss --images out/maps  error maps, signed maps, one contact sheet

Exit codes as for bench: 0 ok, 1 run failed, 2 wrong input, 3 the machine lacks what is needed.)";
} // namespace

int RunCommand::main(int argc, char** argv, RunConfig::Mode mode, const std::string& modesFooter) {
    RunConfig config;
    config.mode = mode;
    bool listOnly = false;
    const std::string footer = mode == RunConfig::Mode::Accuracy ? kAccuracyFooter : modesFooter;
    std::string imagesDir; // bench accuracy --images
    if (int code = RunOptions::parse(argc, argv, config, listOnly, footer, &imagesDir); code >= 0)
        return code;
    if (listOnly) {
        ConsoleReport::printTechniqueList(std::cout);
        return 0;
    }
    return runMeasured(config, imagesDir);
}

} // namespace sb
