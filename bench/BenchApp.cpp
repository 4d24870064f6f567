#include "bench/BenchApp.h"

#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>

#include "bench/AccuracyEvaluator.h"
#include "bench/BottleneckCommand.h"
#include "bench/CliParse.h"
#include "bench/ConsoleReport.h"
#include "bench/CsvWriter.h"
#include "bench/Environment.h"
#include "bench/ExportCommand.h"
#include "bench/FiguresCommand.h"
#include "bench/Harness.h"
#include "bench/ImageWriter.h"
#include "bench/Measurement.h"
#include "bench/MergeCommand.h"
#include "bench/QualitySweep.h"
#include "bench/ResultRow.h"
#include "bench/RowExport.h"
#include "bench/SamplesFile.h"
#include "bench/SweepCommand.h"
#include "bench/SweepWorker.h"
#include "bench/Viewer.h"
#include "core/Error.h"
#include "core/Strings.h"
#include "gl/backends/BackendRegistry.h"
#include "scenes/SceneLoader.h"
#include "techniques/TechniqueRegistry.h"

namespace sb {

namespace {
const char* kFooter = R"(Modes:
  bench [options]                  measure frame times (the default)
  bench accuracy [options]         measure, then judge each technique's visibility against the exact
                                   Embree reference at the same pixels (errors, NaN count, stability);
                                   --sweep walks every quality knob (accuracy against time)
  bench sweep [FILE.json] [axes]   every combination of techniques, scenes, instances, scale, submit,
                                   camera, size, light; --resume, --shard i/N (bench sweep --help)
  bench bottleneck [axes]          is each technique CPU-, vertex- or fill-limited here? (thesis 6.2)
  bench figures                    rerun and replot the reproduced figures of results/figures/
  bench merge -o OUT IN...         join the CSVs of a sharded sweep
  bench export IN.csv --format md  a result CSV as a Markdown table, JSON or CSV

Examples:
  bench                                            shadowmap, aircraft x200, 1024x1024 (the default run)
  bench -t none -t shadowmap --instances 200       baseline and technique side by side
  bench -t shadowmap:resolution=4096:pcf=3         properties inline (see --list for every knob)
  bench --submit immediate --frames 20             the CPU-bound submission path of the thesis
  bench --scene teapot --camera near --scale 10    fill-bound variant
  bench --csv results.csv --samples frames.csv     append a row per technique, keep per-frame samples
  bench --screenshot out.png --visibility vis.png  images of the last frame
  bench --model path/to/model.obj                  your own caster through assimp
  bench --window                                   on-screen viewer (GLFW): drag to orbit, Tab switches
  bench accuracy -t shadowmap --sweep --csv acc.csv  error against time for every shadowmap knob
  bench -t none -t shadowmap --repeat 5            interleaved rounds: ratios from runs side by side
  bench -t none -t shadowmap --format json         the rows as JSON on stdout (also csv, md)
  bench sweep -t none -t shadowmap -n 1,50,100,200 --csv inst.csv
  bench bottleneck -t none -t shadowmap -n 100 --csv bn.csv

Exit codes: 0 ok, 1 run failed (GL error, I/O), 2 bad input, 3 unsupported on this GL context.)";

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
        ConsoleReport::printTable(log, harness, runs);
    }
    if (config.repeat > 1) ConsoleReport::printPairedRatios(log, runs, config.repeat);
    if (!config.csvPath.empty() && !config.quiet) log << "rows appended to " << config.csvPath << "\n";
    if (config.format != RowFormat::Console)
        std::cout << RowExport::format(CsvWriter::toTable(rows), config.format);
}
} // namespace

std::pair<int, int> BenchApp::parseSize(const std::string& text) {
    size_t x = text.find_first_of("xX");
    auto bad = [&] {
        return Error("--size " + text + ": expected WIDTHxHEIGHT with each in [16, 16384], e.g. 1024x1024");
    };
    if (x == std::string::npos) throw bad();
    try {
        size_t a = 0, b = 0;
        int w = std::stoi(text.substr(0, x), &a);
        int h = std::stoi(text.substr(x + 1), &b);
        if (a != x || b != text.size() - x - 1 || w < 16 || h < 16 || w > 16384 || h > 16384) throw bad();
        return {w, h};
    } catch (const std::logic_error&) {
        throw bad();
    }
}

RunConfig BenchApp::parseArgs(const std::vector<std::string>& args, RunConfig::Mode mode) {
    std::vector<std::string> argv{"bench"};
    argv.insert(argv.end(), args.begin(), args.end());
    std::vector<char*> pointers;
    for (std::string& a : argv) pointers.push_back(a.data());
    RunConfig config;
    config.mode = mode;
    bool listOnly = false;
    if (parse(int(pointers.size()), pointers.data(), config, listOnly) >= 0 || listOnly)
        throw Error("options '" + join(args, " ") + "': --help and --list do not belong here");
    return config;
}

int BenchApp::parse(int argc, char** argv, RunConfig& c, bool& listOnly) {
    CLI::App app{"shadowbench: measure real-time shadow techniques on the same scenes", "bench"};
    app.footer(kFooter);
    app.get_formatter()->column_width(34);
    std::vector<std::string> techniques;
    std::string size = "1024x1024", submit = "retained", backend = "auto", light;
    int instances = -1, tess = -1;
    int64_t seed = -1;
    double maxMemoryGiB = double(c.sceneOptions.memoryLimitBytes) / double(1ull << 30);
    bool window = false, noTimerCheck = false;
    app.add_flag("--list", listOnly, "list techniques (effects, passes, properties) and scenes, then exit");
    app.add_option("-t,--technique", techniques,
                   "technique[:prop=value...], repeatable (default shadowmap); see --list");
    app.add_option("--scene", c.scene, "built-in scene name or scene JSON file")->capture_default_str();
    app.add_option("--model", c.sceneOptions.modelPath,
                   "model file (obj, gltf, 3ds ...) replacing the layout mesh");
    app.add_option("-n,--instances", instances,
                   "number of layout instances (scene default: 200 for aircraft)");
    app.add_option("--scale", c.sceneOptions.scale,
                   "scale of every layout instance (10: fill-bound, 0.01: vertex-bound)")
        ->capture_default_str();
    app.add_option("--seed", seed, "layout seed (same seed, same scene)");
    app.add_option("--tess", tess, "tessellation of every generated mesh (vertex load)");
    app.add_option("--tess-factor", c.sceneOptions.tessellationFactor,
                   "multiply every generated mesh's tessellation (0.5: vertex load down)")
        ->capture_default_str();
    app.add_option("--light", light, "replace every light's type: directional, point, spot");
    app.add_option("--camera", c.camera, "camera preset: far, mid, near, top")->capture_default_str();
    app.add_option("--size", size, "render target WIDTHxHEIGHT")->capture_default_str();
    app.add_option("--submit", submit, "submission: " + submitModes().list())->capture_default_str();
    app.add_option("--frames", c.frames, "measured frames")->capture_default_str();
    app.add_option("--seconds", c.seconds, "measure for this many seconds instead of --frames");
    app.add_option("--warmup", c.warmup, "discarded warm-up frames")->capture_default_str();
    app.add_option("--backend", backend, backendNames())->capture_default_str();
    app.add_option("--gpu", c.context.gpu, "EGL device index (implies egl-device under auto)");
    app.add_flag("--window", window, "on-screen viewer (GLFW) instead of a measurement");
    app.add_option("--window-frames", c.windowFrames,
                   "--window: quit after N frames (scripted checks; 0 = never)");
    app.add_option("--csv", c.csvPath, "append one row per technique to this CSV file (atomic)");
    app.add_option("--samples", c.samplesPath, "write per-frame samples to this CSV file");
    app.add_option("--screenshot", c.screenshotPath, "write the last frame's colour image (PNG)");
    app.add_option("--visibility", c.visibilityPath, "write the last frame's visibility target (PNG)");
    app.add_flag("--no-timer-check", noTimerCheck,
                 "skip the GPU-timer trust calibration (verdict: unchecked)");
    app.add_option("--max-memory-gib", maxMemoryGiB, "refuse scenes estimated above this memory")
        ->capture_default_str();
    app.add_flag("-q,--quiet", c.quiet, "print only the table");
    app.add_option("--repeat", c.repeat,
                   "rounds: measure the techniques in turn K times (A B, A B ...); ratios within a round")
        ->capture_default_str();
    std::string format = "console";
    app.add_option("--format", format, "stdout: console (tables), csv, json or md (the rows)")
        ->capture_default_str();
    bool noStability = false;
    app.add_flag("--sweep", c.sweep, "accuracy: walk each technique's quality knobs (see --list)");
    app.add_option("--light-index", c.accuracyLight, "accuracy: which light to judge")->capture_default_str();
    app.add_option("--ref-samples", c.referenceSamples, "accuracy: reference samples per pixel (area lights)")
        ->capture_default_str();
    app.add_flag("--no-stability", noStability, "accuracy: skip perturbation gain and flicker");
    const int code =
        parseCli(app, argc, argv, c.mode == RunConfig::Mode::Accuracy ? "bench accuracy" : "bench");
    if (code >= 0 || listOnly) return code;
    c.stability = !noStability;
    c.format = parseRowFormat(format);
    if (c.repeat < 1 || c.repeat > 1000)
        throw Error("--repeat " + std::to_string(c.repeat) + ": expected 1..1000");
    if (c.mode != RunConfig::Mode::Accuracy && (c.sweep || noStability))
        throw Error("--sweep and --no-stability belong to `bench accuracy` (see bench --help)");
    if (c.referenceSamples < 1 || c.referenceSamples > 4096) throw Error("--ref-samples: expected 1..4096");
    if (c.accuracyLight < 0 || c.accuracyLight >= kMaxLights)
        throw Error("--light-index: expected 0.." + std::to_string(kMaxLights - 1));
    if (!techniques.empty()) {
        c.techniques.clear();
        for (const std::string& t : techniques) c.techniques.push_back(TechniqueSpec::parse(t));
    }
    std::tie(c.width, c.height) = parseSize(size);
    auto mode = parseSubmitMode(submit);
    if (!mode) throw Error("--submit " + submit + ": expected " + submitModes().choices());
    c.submit = *mode;
    c.context.backend = window ? Backend::Glfw : parseBackend(backend);
    c.context.visibleWindow = window;
    c.context.width = c.width;
    c.context.height = c.height;
    if (instances != -1) {
        if (instances < 1) throw Error("--instances " + std::to_string(instances) + ": must be at least 1");
        c.sceneOptions.instances = uint32_t(instances);
    }
    if (tess != -1) {
        if (tess < 1 || tess > 1024) throw Error("--tess " + std::to_string(tess) + ": expected 1..1024");
        c.sceneOptions.tessellation = tess;
    }
    if (seed != -1) {
        if (seed < 0 || seed > 0xffffffffll) throw Error("--seed: expected 0..4294967295");
        c.sceneOptions.seed = uint32_t(seed);
    }
    if (!light.empty()) {
        auto t = parseLightType(light);
        if (!t) throw Error("--light " + light + ": expected directional, point or spot");
        c.sceneOptions.lightType = *t;
    }
    if (!(c.sceneOptions.tessellationFactor >= 0.05f && c.sceneOptions.tessellationFactor <= 20.0f))
        throw Error("--tess-factor: expected a number in [0.05, 20]");
    if (!(std::isfinite(c.sceneOptions.scale) && c.sceneOptions.scale > 0.0f && c.sceneOptions.scale <= 1e6f))
        throw Error("--scale: expected a finite number in (0, 1e6]");
    if (c.frames < 1) throw Error("--frames " + std::to_string(c.frames) + ": must be at least 1");
    if (c.warmup < 0) throw Error("--warmup: must be 0 or more");
    if (c.windowFrames < 0) throw Error("--window-frames: must be 0 or more");
    if (!(c.seconds >= 0.0 && c.seconds <= 86400.0)) throw Error("--seconds: expected 0..86400");
    if (!(maxMemoryGiB > 0.0)) throw Error("--max-memory-gib: must be positive");
    c.sceneOptions.memoryLimitBytes = uint64_t(maxMemoryGiB * double(1ull << 30));
    c.checkTimer = !noTimerCheck;
    return -1;
}

std::vector<TechniqueSpec> BenchApp::configurations(const RunConfig& config) {
    std::vector<TechniqueSpec> specs;
    for (const TechniqueSpec& spec : config.techniques) {
        auto expanded = config.sweep ? QualitySweep::expand(spec) : std::vector<TechniqueSpec>{spec};
        specs.insert(specs.end(), expanded.begin(), expanded.end());
    }
    return specs;
}

int BenchApp::run(const RunConfig& config) {
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

int BenchApp::dispatch(int argc, char** argv) {
    const std::string sub = argc > 1 ? argv[1] : "";
    // Subcommands get argv from their own name on, as if they were programs of their own.
    if (sub == "sweep") return SweepCommand::main(argc - 1, argv + 1);
    if (sub == "bottleneck") return BottleneckCommand::main(argc - 1, argv + 1);
    if (sub == "figures") return FiguresCommand::main(argc - 1, argv + 1);
    if (sub == "merge") return MergeCommand::main(argc - 1, argv + 1);
    if (sub == "export") return ExportCommand::main(argc - 1, argv + 1);
    if (sub == "sweep-worker") {
        if (argc != 3)
            throw Error("usage: bench sweep-worker JOB.json (started by bench sweep, not by hand)");
        return SweepWorker::run(argv[2]);
    }
    RunConfig config;
    bool listOnly = false;
    if (sub == "accuracy") {
        config.mode = RunConfig::Mode::Accuracy;
        argv[1] = argv[0]; // the rest parses like a normal run
        ++argv;
        --argc;
    }
    int code = parse(argc, argv, config, listOnly);
    if (code >= 0) return code;
    if (listOnly) {
        ConsoleReport::printTechniqueList(std::cout);
        return 0;
    }
    return run(config);
}

int BenchApp::main(int argc, char** argv) {
    try {
        return dispatch(argc, argv);
    } catch (const Error& e) {
        std::cerr << "bench: error: " << e.what() << "\n";
        return int(e.code());
    } catch (const std::exception& e) {
        std::cerr << "bench: error: " << e.what() << "\n";
        return int(ExitCode::Failure);
    }
}

} // namespace sb
