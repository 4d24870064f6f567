#include "bench/RunCommand.h"

#include <filesystem>
#include <iostream>
#include <memory>

#include "bench/BenchApp.h"
#include "bench/output/CsvWriter.h"
#include "bench/output/ImageWriter.h"
#include "bench/output/RowExport.h"
#include "bench/run/AccuracyEvaluator.h"
#include "bench/run/ConsoleReport.h"
#include "bench/run/Environment.h"
#include "bench/run/Harness.h"
#include "bench/run/Measurement.h"
#include "bench/run/QualitySweep.h"
#include "bench/run/RunOptions.h"
#include "bench/run/SamplesFile.h"
#include "bench/viewer/Viewer.h"
#include "core/Error.h"
#include "techniques/TechniqueRegistry.h"

namespace sb {

namespace {
std::string withSuffix(const std::string& path, const std::string& suffix) {
    std::filesystem::path p(path);
    return (p.parent_path() / (p.stem().string() + "_" + suffix + p.extension().string())).string();
}

void writeImages(const RunConfig& config, Harness& harness, const std::string& technique) {
    bool several = config.techniques.size() > 1;
    if (!config.screenshotPath.empty())
        ImageWriter::writeColor(harness.targets(), several ? withSuffix(config.screenshotPath, technique)
                                                           : config.screenshotPath);
    if (!config.visibilityPath.empty()) {
        std::string base = several ? withSuffix(config.visibilityPath, technique) : config.visibilityPath;
        size_t lights = std::max<size_t>(1, std::min<size_t>(harness.scene().lights.size(), kMaxLights));
        for (size_t i = 0; i < lights; ++i)
            ImageWriter::writeVisibility(harness.targets(), int(i),
                                         i == 0 ? base : withSuffix(base, "light" + std::to_string(i)));
    }
}
/// Progress and tables go to stdout, unless stdout carries the rows in a machine format (--format).
std::ostream& logStream(const RunConfig& config) {
    return config.format == RowFormat::Console ? std::cout : std::cerr;
}

/// The end of a run: the console table (and, with several rounds, the paired ratios), or the rows in
/// the format --format asked for.
void report(const RunConfig& config, const Harness& harness, const std::vector<Measurement>& results) {
    std::ostream& log = logStream(config);
    std::vector<RunResult> runs;
    std::vector<CsvRow> rows;
    for (const Measurement& m : results) {
        runs.push_back(m.run);
        rows.push_back(m.row);
    }
    if (config.mode == RunConfig::Mode::Accuracy) {
        std::vector<std::pair<RunResult, AccuracyResult>> judged;
        for (const Measurement& m : results) judged.emplace_back(m.run, *m.accuracy);
        ConsoleReport::printAccuracyTable(log, judged);
    } else {
        ConsoleReport::printTable(log, harness, runs, config.repeat);
    }
    if (config.repeat > 1) ConsoleReport::printPairedRatios(log, runs, config.repeat);
    if (!config.csvPath.empty() && !config.quiet) log << "rows appended to " << config.csvPath << "\n";
    if (config.format != RowFormat::Console)
        std::cout << RowExport::format(CsvWriter::toTable(rows), config.format);
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

int RunCommand::run(const RunConfig& config) {
    // Declared before the techniques so that it is destroyed after them: techniques release GL objects
    // in their destructors, which needs the harness's context (also when an exception unwinds).
    std::unique_ptr<Harness> harnessOwner;
    const bool accuracy = config.mode == RunConfig::Mode::Accuracy;
    // Validate everything that needs no GL first: a typo fails in milliseconds, not after a run.
    const std::vector<TechniqueSpec> specs = configurations(config);
    std::vector<std::unique_ptr<Technique>> techniques;
    for (const TechniqueSpec& spec : specs) techniques.push_back(TechniqueRegistry::create(spec));
    if (!config.csvPath.empty()) CsvWriter::checkWritable(config.csvPath);
    if (!config.samplesPath.empty()) CsvWriter::checkWritable(config.samplesPath);

    harnessOwner = std::make_unique<Harness>(config);
    Harness& harness = *harnessOwner;
    if (!accuracy && config.context.backend == Backend::Glfw && config.context.visibleWindow) {
        int code = Viewer::run(harness, techniques, config.windowFrames);
        // The last frame shown, when asked for (the viewer draws with the same targets).
        if (!config.screenshotPath.empty()) ImageWriter::writeColor(harness.targets(), config.screenshotPath);
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

    Environment env = Environment::capture();
    std::vector<Measurement> results;
    const std::string baseline = specs.front().toString();
    const size_t total = specs.size() * size_t(config.repeat);
    // Rounds interleave the techniques (A B C, A B C ...): ratios are taken within a round, between
    // runs measured next to each other.
    for (int round = 1; round <= config.repeat; ++round) {
        std::optional<double> baselineWall;
        for (size_t i = 0; i < techniques.size(); ++i) {
            Technique& technique = *techniques[i];
            if (!config.quiet)
                log << "[" << results.size() + 1 << "/" << total << "] " << technique.name() << " "
                    << technique.properties().toString() << " ..." << std::flush;
            Measurement m = Measurement::take(harness, technique, evaluator.get(), options, env);
            if (i == 0) baselineWall = m.run.wall.median;
            m.addRound(round, baseline, baselineWall);
            if (!config.quiet) {
                log << " " << m.run.wall.n << " frames, median " << m.run.wall.median << " ms";
                if (m.accuracy) log << ", " << m.accuracy->hard.wrongPct << "% wrong";
                log << "\n";
            }
            if (!config.csvPath.empty()) CsvWriter::appendRows(config.csvPath, {m.row});
            if (!config.samplesPath.empty()) SamplesFile::append(config.samplesPath, harness, m.run);
            writeImages(config, harness, technique.name());
            results.push_back(std::move(m));
        }
    }
    report(config, harness, results);
    return 0;
}

int RunCommand::main(int argc, char** argv, RunConfig::Mode mode) {
    RunConfig config;
    config.mode = mode;
    bool listOnly = false;
    if (int code = RunOptions::parse(argc, argv, config, listOnly, BenchApp::helpFooter()); code >= 0)
        return code;
    if (listOnly) {
        ConsoleReport::printTechniqueList(std::cout);
        return 0;
    }
    return run(config);
}

} // namespace sb
