#include "bench/lib/sweep/SweepWorker.h"

#include <csignal>
#include <cstdlib>
#include <iostream>
#include <map>
#include <memory>

#include "bench/lib/harness/Harness.h"
#include "bench/lib/harness/VulkanHarness.h"
#include "bench/lib/measure/Measurement.h"
#include "bench/lib/options/RunOptions.h"
#include "bench/lib/output/ResultColumns.h"
#include "bench/lib/sweep/SweepJob.h"
#include "bench/lib/sweep/SweepRows.h"
#include "core/Error.h"
#include "gl/DebugOutput.h"
#include "registry/TechniqueRegistry.h"

namespace sb {

namespace {

RunConfig parseJobArgs(const SweepJob& job) {
    RunConfig config =
        RunOptions::parseArgs(job.args, job.mode == SweepPlan::Mode::Accuracy ? RunConfig::Mode::Accuracy
                                                                              : RunConfig::Mode::Measure);
    config.quiet = true;
    return config;
}

/// The test seam of the header: acts when `index` is the configuration named in the environment.
void injectFault(size_t index) {
    const char* spec = std::getenv("SHADOWBENCH_FAULT_INJECT");
    if (!spec) return;
    const std::string s(spec);
    const size_t colon = s.find(':');
    if (colon == std::string::npos || s.substr(colon + 1) != std::to_string(index)) return;
    const std::string kind = s.substr(0, colon);
    if (kind == "crash") std::raise(SIGSEGV);
    if (kind == "glerror") {
        glEnable(GLenum(0x7FFF)); // GL_INVALID_ENUM, reported through KHR_debug like a real one
        DebugOutput::check();
    }
}

/// Runs the rows; reports each on stdout. Throws on the first failure, with `current` naming it.
void runRows(const SweepJob& job, const RunConfig& config, size_t& current) {
    // The harness outlives the techniques (they release API objects).
    std::unique_ptr<MeasuredHarness> harness;
    const bool vulkan = config.api == RunConfig::Api::Vulkan;
    std::map<std::string, std::unique_ptr<Technique>> techniques;
    for (const PlannedRow& row : job.rows)
        if (!techniques.count(row.technique))
            techniques[row.technique] = TechniqueRegistry::create(TechniqueSpec::parse(row.technique),
                                                                  vulkan ? Api::Vulkan : Api::GL);
    current = job.rows.front().index; // a failure to start is the first row's
    if (vulkan)
        harness = std::make_unique<VulkanHarness>(config);
    else
        harness = std::make_unique<Harness>(config);
    // The sweep's verdict is the GL timer's: a Vulkan worker checks its own timestamps.
    if (job.timer && !vulkan)
        harness->setTimerVerdict(*job.timer);
    else if (config.checkTimer)
        harness->calibrateTimer();
    // Accuracy is judged by the harness that rendered the frame (its own G-buffer), on either API.
    std::unique_ptr<AccuracyEvaluator> evaluator;
    if (config.mode == RunConfig::Mode::Accuracy) evaluator = std::make_unique<AccuracyEvaluator>(*harness);
    AccuracyOptions options;
    options.light = config.accuracyLight;
    options.referenceSamples = config.referenceSamples;
    options.stability = config.stability;
    Environment env = Environment::capture();
    std::map<int, double> baselineWall = job.baselineWalls; // per round
    for (const PlannedRow& row : job.rows) {
        current = row.index;
        std::cout << WorkerMessage::begin(row.index) << std::endl;
        injectFault(row.index);
        Measurement m =
            Measurement::take(*harness, *techniques[row.technique], evaluator.get(), options, env);
        if (row.technique == job.baseline) baselineWall[row.round] = m.run.wall.median;
        const auto base = baselineWall.find(row.round);
        m.addRound(row.round, job.baseline,
                   base == baselineWall.end() ? std::nullopt : std::optional<double>(base->second));
        m.row.emplace_back(col::kTechniqueSpec, row.technique);
        m.row.emplace_back(col::kConfigIndex, std::to_string(row.index));
        m.row.insert(m.row.end(), job.tags.begin(), job.tags.end());
        SweepRows::write(job.csvPath, {m.row}, job.replacesFailed.count(row.index) > 0);
        std::cout << WorkerMessage::done(row.index, m.run.wall.median) << std::endl;
    }
}

} // namespace

int SweepWorker::run(const std::string& jobPath) {
    size_t current = 0;
    try {
        const SweepJob job = SweepJob::load(jobPath);
        if (job.rows.empty()) return 0;
        current = job.rows.front().index;
        runRows(job, parseJobArgs(job), current);
        return 0;
    } catch (const Error& e) {
        std::cout << WorkerMessage::failed(current, int(e.code()), e.what()) << std::endl;
        std::cerr << "bench: error: " << e.what() << "\n";
        return int(e.code());
    } catch (const std::exception& e) {
        std::cout << WorkerMessage::failed(current, int(ExitCode::Failure), e.what()) << std::endl;
        std::cerr << "bench: error: " << e.what() << "\n";
        return int(ExitCode::Failure);
    }
}

} // namespace sb
