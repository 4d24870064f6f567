#include "bench/lib/options/RunOptions.h"

#include <cmath>
#include <cstdio>
#include <optional>

#include <CLI/CLI.hpp>

#include "bench/lib/options/CliParse.h"
#include "bench/lib/options/DriverOption.h"
#include "core/Error.h"
#include "core/Strings.h"
#include "gl/FrameTargets.h"
#include "gl/backends/BackendRegistry.h"
#include "scenes/Scene.h"

namespace sb {

std::pair<int, int> RunOptions::parseSize(const std::string& text) {
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

RunConfig RunOptions::parseArgs(const std::vector<std::string>& args, RunConfig::Mode mode) {
    std::vector<std::string> argv{"bench"};
    argv.insert(argv.end(), args.begin(), args.end());
    std::vector<char*> pointers;
    for (std::string& a : argv) pointers.push_back(a.data());
    RunConfig config;
    config.mode = mode;
    bool listOnly = false;
    if (parse(int(pointers.size()), pointers.data(), config, listOnly) >= 0 || listOnly)
        throw Error("options '" + join(args, " ") + "': --help and --list do not belong here");
    // A sweep's workers, the bottleneck study and the figures measure on the API the options name, and
    // accuracy is judged by the harness that rendered the frame (SweepWorker).
    return config;
}

void RunOptions::requireGl(const RunConfig& config, const std::string& command) {
    if (config.api == RunConfig::Api::Vulkan)
        throw Error(command + " renders with GL only; --api vulkan is taken by `bench` and `bench accuracy`",
                    ExitCode::Unsupported);
}

namespace {

// Bounds that keep every derived quantity finite and meaningful. --scale multiplies every layout
// instance: below 1e-4 an aircraft is smaller than float precision at the scene's extent and the camera
// fit fails with a message about the camera instead of the option; above 1e4 the scene's bounds
// overflow the depth range. --max-memory-gib: 1 PiB, far beyond any machine, and exact in uint64 bytes.
constexpr double kMinScale = 1e-4, kMaxScale = 1e4;
constexpr double kMaxMemoryGiB = 1024.0 * 1024.0;

std::string formatNumber(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

/// An option that names a file or folder and was given as "" would silently mean "not given".
void requireNonEmptyPaths(const CLI::App& app) {
    for (const char* name : {"--csv", "--samples", "--screenshot", "--visibility", "--dump-shaders",
                             "--model", "--scene", "--calibration", "--calibration-seed", "--images"}) {
        const CLI::Option* o = app.get_option_no_throw(name);
        if (o && o->count() > 0 && o->as<std::string>().empty())
            throw Error(std::string(name) + ": the path is empty");
    }
}

// Device indices: far beyond any machine's count of EGL or Vulkan devices, and small enough that an
// index that names no device is refused by the context with the devices there are.
constexpr int kMaxDeviceIndex = 1023;

/// What CLI11 fills before it is checked: texts, and the numbers whose absence means "the scene's" or
/// "the default". Those are optional, set only when the option is given, so that no value a user can
/// type (-1, 0) is mistaken for "not given".
struct RawOptions {
    std::vector<std::string> techniques;
    std::string size = "1024x1024", submit = "retained", backend = "auto", light, lighting,
                format = "console";
    std::string backFaces = "cull";
    std::string api = "gl", driver;
    std::optional<int> instances, tess, pathFrames, gpu, vkDevice;
    std::optional<int64_t> seed;
    std::optional<double> pathTime;
    double maxMemoryGiB = 0.0;
    bool window = false, noTimerCheck = false, noStability = false;
};

/// An option whose value lands in `into` only when it is given.
template <typename T>
CLI::Option* addOptional(CLI::App& app, const std::string& name, std::optional<T>& into,
                         const std::string& help) {
    return app.add_option_function<T>(
        name, [&into](const T& value) { into = value; }, help);
}

/// Throws sb::Error naming `option` and the accepted range when `value` lies outside [low, high].
void requireRange(const char* option, int64_t value, int64_t low, int64_t high) {
    if (value < low || value > high)
        throw Error(std::string(option) + " " + std::to_string(value) + ": expected " + std::to_string(low) +
                    ".." + std::to_string(high));
}

/// Every option of a run, in --help's order; RunConfig fields that need no check are bound directly.
void addOptions(CLI::App& app, RunConfig& c, RawOptions& raw, bool& listOnly) {
    app.add_flag("--list", listOnly, "list techniques (effects, passes, properties) and scenes, then exit");
    app.add_option("-t,--technique", raw.techniques,
                   "technique[:prop=value...], repeatable (default shadowmap); see --list");
    app.add_option("--scene", c.scene, "built-in scene name or scene JSON file")->capture_default_str();
    app.add_option("--model", c.sceneOptions.modelPath,
                   "model file (obj, gltf, 3ds ...) replacing the layout mesh");
    addOptional(app, "-n,--instances", raw.instances,
                "number of layout instances (scene default: 200 for aircraft)");
    app.add_option("--scale", c.sceneOptions.scale,
                   "scale of every layout instance (10: fill-bound, 0.01: vertex-bound)")
        ->capture_default_str();
    addOptional(app, "--seed", raw.seed, "layout seed (same seed, same scene)");
    addOptional(app, "--tess", raw.tess, "tessellation of every generated mesh (vertex load)");
    app.add_option("--tess-factor", c.sceneOptions.tessellationFactor,
                   "multiply every generated mesh's tessellation (0.5: vertex load down)")
        ->capture_default_str();
    app.add_option("--light", raw.light, "replace every light's type: " + lightTypeNames().list());
    app.add_option("--lighting", raw.lighting,
                   "where the lit passes evaluate the lights: fragment or vertex (interpolated, Gouraud: "
                   "glmark2's model, a different image under point and spot lights) (default: the scene's, "
                   "else fragment; CSV column lighting)");
    app.add_option("--camera", c.camera,
                   "camera preset: far, mid, near, top (path: a moving scene's camera path)")
        ->capture_default_str();
    addOptional(
        app, "--time", raw.pathTime,
        "a scene in motion: freeze it at this path time in [0, 1] (default: frames move along the path)");
    addOptional(app, "--path-frames", raw.pathFrames,
                "a scene in motion: frames per pass along its path (default: the scene's)");
    app.add_option("--size", raw.size, "render target WIDTHxHEIGHT")->capture_default_str();
    app.add_option("--submit", raw.submit, "submission: " + submitModes().list())->capture_default_str();
    app.add_option("--back-faces", raw.backFaces,
                   "cull or draw: cull the back faces of closed meshes where the image cannot change, or "
                   "draw every face (before/after comparisons)")
        ->capture_default_str();
    app.add_option("--frames", c.frames, "measured frames")->capture_default_str();
    app.add_option("--seconds", c.seconds, "measure for this many seconds instead of --frames");
    app.add_option("--warmup", c.warmup, "discarded warm-up frames")->capture_default_str();
    app.add_option("--api", raw.api,
                   "gl or vulkan: the API the frames are drawn with (vulkan: lavapipe by default; techniques "
                   "with a Vulkan form in --list)")
        ->capture_default_str();
    addOptional(app, "--vk-device", raw.vkDevice,
                "--api vulkan: device index as --list shows (default: lavapipe, else the first)");
    app.add_flag("--vk-validation", c.vulkan.validation,
                 "--api vulkan: Khronos validation layer on, its messages printed (slows every frame)");
    DriverOption::add(app, raw.driver);
    app.add_option("--backend", raw.backend, backendNames())->capture_default_str();
    addOptional(app, "--gpu", raw.gpu, "EGL device index (implies egl-device under auto)");
    app.add_flag("--window", raw.window, "on-screen viewer (GLFW) instead of a measurement");
    app.add_option("--window-frames", c.windowFrames,
                   "--window: quit after N frames (scripted checks; 0 = never)");
    app.add_option("--csv", c.csvPath, "append one row per technique to this CSV file (atomic)");
    app.add_option("--samples", c.samplesPath, "write per-frame samples to this CSV file");
    app.add_option("--trace", c.tracePath, "write per-pass timelines (Chrome trace JSON, for Perfetto)");
    app.add_option("--screenshot", c.screenshotPath, "write the last frame's colour image (PNG)");
    app.add_option("--visibility", c.visibilityPath, "write the last frame's visibility target (PNG)");
    app.add_option("--dump-shaders", c.dumpShadersPath,
                   "write every shader stage as compiled to DIR/technique/program/permutation/stage.ext");
    app.add_flag("--no-timer-check", raw.noTimerCheck,
                 "skip the GPU-timer trust calibration (verdict: unchecked)");
    app.add_option(
           "--max-memory-gib", raw.maxMemoryGiB,
           "refuse a run whose estimated memory (scene, model file, frame targets, technique) exceeds this")
        ->capture_default_str();
    app.add_flag("-q,--quiet", c.quiet, "print only the table");
    app.add_flag("--strict-effects", c.strictEffects,
                 "refuse (exit 3) a technique that cannot produce an effect the scene asks for, instead of "
                 "measuring it with a warning");
    app.add_option("--auto-max-wrong", c.autoMaxWrongPct,
                   "-t auto: the most a candidate may misplace of the reference's shadow (misclassified "
                   "samples over shadowed ones, %)")
        ->capture_default_str();
    app.add_option(
        "--calibration", c.calibrationPath,
        "-t auto: the calibration cache (CSV; default $XDG_CACHE_HOME/shadowbench/auto-calibration.csv, "
        "else ~/.cache/shadowbench/...)");
    app.add_option(
        "--calibration-seed", c.calibrationSeedPath,
        "-t auto: a calibration read before the cache and never written (results/ci/auto-calibration.csv)");
    app.add_flag("--recalibrate", c.recalibrate, "-t auto: measure every candidate again");
    app.add_option("--repeat", c.repeat,
                   "rounds: measure the techniques in turn K times (A B, A B ...); ratios within a round")
        ->capture_default_str();
    app.add_option("--format", raw.format, "stdout: " + rowFormatChoices() + " (the rows)")
        ->capture_default_str();
    // `bench accuracy`'s own options: their group under `bench accuracy --help`, hidden (an empty group)
    // from the plain run's help, which refuses them.
    const std::string accuracy = c.mode == RunConfig::Mode::Accuracy ? "Accuracy options" : "";
    app.add_flag("--sweep", c.sweep, "walk each technique's quality knobs (see --list): error against time")
        ->group(accuracy);
    app.add_option("--light-index", c.accuracyLight, "which light to judge")
        ->capture_default_str()
        ->group(accuracy);
    app.add_option("--ref-samples", c.referenceSamples, "reference samples per pixel (area lights)")
        ->capture_default_str()
        ->group(accuracy);
    app.add_flag("--no-stability", raw.noStability, "skip perturbation gain and flicker")->group(accuracy);
}

/// Checks the raw options and moves them into `c`. Throws sb::Error naming the option.
void applyOptions(const RawOptions& raw, RunConfig& c) {
    c.stability = !raw.noStability;
    c.format = parseRowFormat(raw.format);
    if (c.repeat < 1 || c.repeat > 1000)
        throw Error("--repeat " + std::to_string(c.repeat) + ": expected 1..1000");
    if (c.mode != RunConfig::Mode::Accuracy && (c.sweep || raw.noStability))
        throw Error("--sweep and --no-stability belong to `bench accuracy` (see bench --help)");
    if (c.referenceSamples < 1 || c.referenceSamples > 4096) throw Error("--ref-samples: expected 1..4096");
    if (!(c.autoMaxWrongPct >= 0.0 && c.autoMaxWrongPct <= 100.0))
        throw Error("--auto-max-wrong: expected a percentage 0..100");
    if (c.accuracyLight < 0 || c.accuracyLight >= kMaxLights)
        throw Error("--light-index: expected 0.." + std::to_string(kMaxLights - 1));
    if (!raw.techniques.empty()) {
        c.techniques.clear();
        for (const std::string& t : raw.techniques) c.techniques.push_back(TechniqueSpec::parse(t));
    }
    std::tie(c.width, c.height) = RunOptions::parseSize(raw.size);
    auto mode = parseSubmitMode(raw.submit);
    if (!mode) throw Error("--submit " + raw.submit + ": expected " + submitModes().choices());
    c.submit = *mode;
    const std::optional<BackFaces> backFaces = parseBackFaces(raw.backFaces);
    if (!backFaces) throw Error("--back-faces " + raw.backFaces + ": expected cull or draw");
    c.backFaces = *backFaces;
    c.context.backend = raw.window ? Backend::Glfw : parseBackend(raw.backend);
    c.context.visibleWindow = raw.window;
    c.context.width = c.width;
    c.context.height = c.height;
    if (raw.instances) {
        if (*raw.instances < 1)
            throw Error("--instances " + std::to_string(*raw.instances) + ": must be at least 1");
        c.sceneOptions.instances = uint32_t(*raw.instances);
    }
    if (raw.tess) {
        requireRange("--tess", *raw.tess, 1, 1024);
        c.sceneOptions.tessellation = *raw.tess;
    }
    if (raw.seed) {
        requireRange("--seed", *raw.seed, 0, 0xffffffffll);
        c.sceneOptions.seed = uint32_t(*raw.seed);
    }
    if (!raw.light.empty()) {
        auto t = lightTypeNames().parse(raw.light);
        if (!t) throw Error("--light " + raw.light + ": expected " + lightTypeNames().choices());
        c.sceneOptions.lightType = *t;
    }
    if (!raw.lighting.empty()) {
        const std::optional<LightingRate> rate = parseLightingRate(raw.lighting);
        if (!rate) throw Error("--lighting " + raw.lighting + ": expected " + lightingRateNames().choices());
        c.sceneOptions.lighting = *rate;
    }
    if (!(c.sceneOptions.tessellationFactor >= 0.05f && c.sceneOptions.tessellationFactor <= 20.0f))
        throw Error("--tess-factor: expected a number in [0.05, 20]");
    if (!(c.sceneOptions.scale >= kMinScale && c.sceneOptions.scale <= kMaxScale))
        throw Error("--scale " + formatNumber(c.sceneOptions.scale) + ": expected a number in [" +
                    formatNumber(kMinScale) + ", " + formatNumber(kMaxScale) + "]");
    if (raw.gpu) {
        requireRange("--gpu", *raw.gpu, 0, kMaxDeviceIndex);
        c.context.gpu = *raw.gpu;
    }
    if (raw.gpu && c.context.backend != Backend::Auto && c.context.backend != Backend::EglDevice)
        throw Error("--gpu selects an EGL device, which --backend " + raw.backend +
                    " does not use (use --backend egl-device or auto)");
    if (c.frames < 1) throw Error("--frames " + std::to_string(c.frames) + ": must be at least 1");
    if (raw.pathTime) {
        if (!(*raw.pathTime >= 0.0 && *raw.pathTime <= 1.0))
            throw Error("--time " + formatNumber(*raw.pathTime) + ": expected a path time in [0, 1]");
        c.pathTime = *raw.pathTime;
    }
    if (raw.pathFrames) {
        requireRange("--path-frames", *raw.pathFrames, 2, 1000000);
        c.pathFrames = *raw.pathFrames;
    }
    if (c.warmup < 0) throw Error("--warmup: must be 0 or more");
    if (c.windowFrames < 0) throw Error("--window-frames: must be 0 or more");
    if (!(c.seconds >= 0.0 && c.seconds <= 86400.0)) throw Error("--seconds: expected 0..86400");
    // Bounded above so that the conversion to bytes cannot overflow (1e30 or inf would wrap to 0).
    if (!(raw.maxMemoryGiB > 0.0 && raw.maxMemoryGiB <= kMaxMemoryGiB))
        throw Error("--max-memory-gib " + formatNumber(raw.maxMemoryGiB) + ": expected a number in (0, " +
                    formatNumber(kMaxMemoryGiB) + "]");
    c.sceneOptions.memoryLimitBytes = uint64_t(raw.maxMemoryGiB * double(1ull << 30));
    c.checkTimer = !raw.noTimerCheck;
    if (raw.api != "gl" && raw.api != "vulkan") throw Error("--api " + raw.api + ": expected gl or vulkan");
    c.api = raw.api == "vulkan" ? RunConfig::Api::Vulkan : RunConfig::Api::GL;
    if (raw.vkDevice) {
        requireRange("--vk-device", *raw.vkDevice, 0, kMaxDeviceIndex);
        c.vulkan.device = *raw.vkDevice;
    }
    if (c.api == RunConfig::Api::GL && (raw.vkDevice || c.vulkan.validation))
        throw Error(std::string(raw.vkDevice ? "--vk-device" : "--vk-validation") +
                    " applies to --api vulkan only");
    // The GL context's options choose nothing on Vulkan: refused rather than accepted and ignored.
    if (c.api == RunConfig::Api::Vulkan && (raw.backend != "auto" || raw.gpu))
        throw Error(std::string(raw.gpu ? "--gpu" : "--backend " + raw.backend) +
                    " chooses the GL context; with --api vulkan the device is chosen with --vk-device");
}

} // namespace

int RunOptions::parse(int argc, char** argv, RunConfig& c, bool& listOnly, const std::string& footer,
                      std::string* imagesDir) {
    const bool accuracy = c.mode == RunConfig::Mode::Accuracy;
    CLI::App app{accuracy
                     ? "bench accuracy: render each technique, then judge its visibility against the exact "
                       "Embree reference at the same pixels"
                     : "shadowbench: measure real-time shadow techniques on the same scenes",
                 accuracy ? "bench accuracy" : "bench"};
    app.footer(footer);
    app.get_formatter()->column_width(34);
    RawOptions raw;
    raw.maxMemoryGiB = double(c.sceneOptions.memoryLimitBytes) / double(1ull << 30);
    addOptions(app, c, raw, listOnly);
    // --images: only where the caller draws the pictures (bench/run/RunCommand.cpp); hidden from and refused
    // by the plain run like the other accuracy options.
    CLI::Option* images = nullptr;
    if (imagesDir)
        images = app.add_option("--images", *imagesDir,
                                "write each technique's and the reference's visibility, an error map (and "
                                "a signed difference map where visibility is not binary) and one contact "
                                "sheet into DIR")
                     ->type_name("DIR")
                     ->group(accuracy ? "Accuracy options" : "");
    const int code = parseCli(app, argc, argv, accuracy ? "bench accuracy" : "bench");
    if (code >= 0 || listOnly) return code;
    requireNonEmptyPaths(app);
    if (images && images->count() > 0 && !accuracy)
        throw Error("--images belongs to `bench accuracy` (see bench accuracy --help)");
    applyOptions(raw, c);
    return -1;
}

} // namespace sb
