#include "bench/golden/GoldenMatrix.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iterator>
#include <memory>
#include <optional>
#include <sstream>
#include <unistd.h>

#include "bench/golden/MatrixVariants.h"
#include "bench/golden/StderrCapture.h"
#include "bench/lib/harness/Harness.h"
#include "bench/lib/harness/VulkanHarness.h"
#include "bench/lib/measure/AccuracyEvaluator.h"
#include "bench/lib/select/AutoResolver.h"
#include "bench/lib/select/Calibration.h"
#include "core/DriverTable.h"
#include "core/Error.h"
#include "core/Paths.h"
#include "registry/TechniqueRegistry.h"
#include "scenes/SceneLoader.h"

namespace sb {

namespace {

/// A scene in motion is judged part way along a short path, reached frame by frame, so that every cell
/// runs its technique's per-frame update (Technique::sceneChanged) before the image is taken.
constexpr int kPathFrames = 8;
constexpr uint64_t kPathStep = 5;
/// The Vulkan axis: the two submission modes Vulkan has (immediate and display lists are GL's own).
constexpr SubmitMode kVulkanModes[] = {SubmitMode::Retained, SubmitMode::Instanced};

/// One cell's run configuration on either API: a frame of `scene` from its matrix camera at the matrix's
/// size, its path's frames where it moves, its layout cut to the matrix's triangles.
RunConfig cellConfig(const std::string& name, const Scene& scene, const std::string& camera, SubmitMode mode,
                     const MatrixOptions& options) {
    RunConfig config = RunConfig::oneFrame(name, camera, options.size, mode);
    if (scene.motion) config.pathFrames = kPathFrames;
    config.sceneOptions.instances = GoldenMatrix::layoutInstances(scene, options);
    return config;
}

std::string cellName(const std::string& technique, const std::string& scene, SubmitMode mode, bool vulkan) {
    return technique + "/" + scene + "/" + submitModeName(mode) + (vulkan ? "/vulkan" : "");
}

/// A variant's reason for having no GL form (MatrixVariant::glRefusal), empty for every other form.
std::string glRefusalOf(const std::string& technique) {
    if (technique == AutoResolver::kName) return "";
    const std::optional<MatrixVariant> v = MatrixVariants::variantOf(technique);
    return v ? v->glRefusal : "";
}

/// Whether the technique of `technique` (a cell's: a name or a variant's spec) has a form on `api`.
bool hasForm(const std::string& technique, Api api) {
    if (api == Api::GL && !glRefusalOf(technique).empty()) return false;
    return TechniqueRegistry::has(MatrixVariants::nameOf(technique), api);
}

/// Why `technique` has no form on `api`, in the registry's words (its refusal names the APIs that have
/// one, or a reason of the technique's own).
std::string noFormReason(const std::string& technique, Api api) {
    if (api == Api::GL && !glRefusalOf(technique).empty()) return glRefusalOf(technique);
    try {
        TechniqueRegistry::create(TechniqueSpec::parse(technique), api);
    } catch (const Error& e) {
        return e.what();
    } catch (const std::exception&) { // a registry row without the form and without words for it
    }
    return technique + " has no " + apiName(api) + " form";
}

/// The refusal of a form whose capabilities this driver lacks (`missing`: the form's own words, naming
/// the capability and the device), or "" when it has them all.
std::string driverRefusal(const std::string& missing) {
    return missing.empty() ? "" : "not on the driver " + DriverTable::current() + ": " + missing;
}

/// Marks `cell` as one this driver cannot run (`refused`: driverRefusal's words), or fails it with
/// MatrixOptions::strictDriver. False when `refused` is empty: the cell is to be rendered.
bool refusedByDriver(MatrixCell& cell, const std::string& refused, const MatrixOptions& options) {
    if (refused.empty()) return false;
    if (options.strictDriver) {
        cell.failure = refused + " (--strict-driver: this driver is the one to run it)";
    } else {
        cell.unsupported = refused;
        cell.refusal = MatrixCell::Refusal::Driver;
    }
    return true;
}

/// Whether any of `techniques` has a GL form (`auto` resolves among them on GL).
bool anyGlForm(const std::vector<std::string>& techniques) {
    return std::any_of(techniques.begin(), techniques.end(),
                       [](const std::string& t) { return t == AutoResolver::kName || hasForm(t, Api::GL); });
}

/// Renders one cell with its stderr captured, telling the observer before and after.
template <class Render>
void addCell(std::vector<MatrixCell>& cells, const std::string& name, const MatrixObserver& observer,
             Render render) {
    if (observer.starting) observer.starting(name);
    MatrixCell cell;
    {
        StderrCapture capture;
        cell = render();
        cell.warnings = capture.take();
    }
    cells.push_back(std::move(cell));
    if (observer.finished) observer.finished(cells);
}

std::vector<std::string> techniquesOf(const MatrixOptions& options) {
    std::vector<std::string> techniques = options.techniques;
    if (techniques.empty()) {
        techniques = MatrixVariants::all();
        techniques.push_back(AutoResolver::kName);
    }
    return techniques;
}

std::vector<SubmitMode> modesRetainedFirst() {
    std::vector<SubmitMode> modes{SubmitMode::Retained};
    for (SubmitMode m : kAllSubmitModes)
        if (m != SubmitMode::Retained) modes.push_back(m);
    return modes;
}

uint8_t toByte(float v) {
    if (!std::isfinite(v)) v = 0.0f;
    return uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

/// GL read-backs are bottom-up; images are top row first.
size_t flippedRow(size_t index, int width, int height) {
    const size_t x = index % size_t(width), y = index / size_t(width);
    return (size_t(height) - 1 - y) * size_t(width) + x;
}

void readImages(int w, int h, const std::vector<float>& vis, const std::vector<unsigned char>& rgba,
                size_t lightCount, MatrixCell& cell) {
    const size_t pixels = size_t(w) * size_t(h);
    const size_t lights = std::min<size_t>(lightCount, 3);
    cell.visibility = {w, h, lights == 1 ? 1 : 3, std::vector<uint8_t>(pixels * (lights == 1 ? 1 : 3), 0)};
    cell.colour = {w, h, 3, std::vector<uint8_t>(pixels * 3)};
    cell.visibilityFloat.assign(pixels * lights, 0.0f);
    for (size_t p = 0; p < pixels; ++p) {
        const size_t out = flippedRow(p, w, h);
        for (size_t l = 0; l < lights; ++l) {
            cell.visibility.pixels[out * size_t(cell.visibility.channels) + l] = toByte(vis[p * 4 + l]);
            cell.visibilityFloat[p * lights + l] = vis[p * 4 + l];
        }
        for (size_t c = 0; c < 3; ++c) cell.colour.pixels[out * 3 + c] = rgba[p * 4 + c];
    }
    cell.sanity = AccuracyMetrics::sanity(vis);
}

AccuracyOptions optionsFor(int light, const MatrixOptions& options) {
    AccuracyOptions o;
    o.light = light;
    o.stability = false;
    o.referenceSamples = options.referenceSamples;
    return o;
}

CellAccuracy scoreLight(const AccuracyEvaluator::Sample& s, int light, const Scene& scene,
                        const MatrixOptions& options) {
    const int w = options.size, h = options.size;
    CellAccuracy a;
    a.hard = AccuracyMetrics::hard(s.technique, s.reference, s.mask, w, h);
    a.soft = AccuracyMetrics::soft(s.technique, s.reference, s.mask);
    a.softReference = scene.lights[size_t(light)].isArea();
    uint64_t shadowed = 0, judged = 0;
    double squares = 0.0, blackSquares = 0.0;
    for (size_t i = 0; i < s.mask.size(); ++i) {
        if (!s.mask[i]) continue;
        ++judged;
        shadowed += s.reference[i] < 0.5f;
        squares += double(1.0f - s.reference[i]) * double(1.0f - s.reference[i]);
        blackSquares += double(s.reference[i]) * double(s.reference[i]);
    }
    a.noShadowPct = judged ? 100.0 * double(shadowed) / double(judged) : 0.0;
    a.noShadowRmse = judged ? std::sqrt(squares / double(judged)) : 0.0;
    a.allShadowRmse = judged ? std::sqrt(blackSquares / double(judged)) : 0.0;
    return a;
}

MatrixCell renderCell(Harness& harness, AccuracyEvaluator& evaluator, const std::string& cellName,
                      const TechniqueSpec& spec, const std::string& scene, const MatrixOptions& options) {
    MatrixCell cell;
    cell.technique = cellName;
    cell.scene = scene;
    cell.mode = harness.config().submit;
    std::unique_ptr<GlTechnique> technique = TechniqueRegistry::create(spec);
    if (refusedByDriver(cell, driverRefusal(technique->checkCapabilities(harness.context())), options))
        return cell;
    harness.seekPath(0); // a scene in motion starts each cell at rest
    try {
        harness.prepare(*technique);
    } catch (const Error& e) {
        if (e.code() != ExitCode::Unsupported) throw;
        cell.unsupported = e.what();
        cell.refusal = MatrixCell::Refusal::Scene;
        return cell;
    }
    if (harness.moving())
        for (uint64_t f = 0; f < kPathStep; ++f) harness.renderFrame(*technique);
    harness.seekPath(kPathStep);
    harness.renderFrame(*technique);
    const size_t lights = harness.scene().lights.size();
    readImages(harness.targets().width(), harness.targets().height(),
               harness.targets().readVisibilityRGBA32F(), harness.targets().readColorRGBA8(), lights, cell);
    for (size_t l = 0; l < lights; ++l) {
        harness.seekPath(kPathStep); // each judged frame is the same frame of the path
        cell.lights.push_back(
            scoreLight(evaluator.judgeFrame(*technique, optionsFor(int(l), options), nullptr), int(l),
                       harness.scene(), options));
    }
    return cell;
}

/// -t auto on the retained harness, as `bench -t auto` resolves it, with a calibration of its own (a
/// temporary cache, measured afresh, in MatrixOptions::autoRounds rounds) so no earlier run's cache
/// decides.
AutoPick resolveAuto(MeasuredHarness& harness, const MatrixOptions& options) {
    RunConfig config = harness.config();
    const std::filesystem::path cache = std::filesystem::temp_directory_path() /
                                        ("shadowbench-matrix-auto-" + std::to_string(::getpid()) + ".csv");
    config.calibrationPath = cache.string();
    config.recalibrate = true;
    std::ostringstream log;
    struct Remove {
        std::filesystem::path path;
        ~Remove() {
            std::error_code ignored;
            std::filesystem::remove(path, ignored);
        }
    } removeCache{cache};
    CalibrationOptions timing;
    timing.frames = options.autoRounds;
    timing.warmup = 0;
    const AutoResolution r = AutoResolver::resolve(harness, config, log, timing);
    AutoPick pick;
    pick.spec = r.spec.toString();
    pick.reason = r.reason;
    pick.request = harness.scene().effects;
    pick.wrongPct = r.chosen.wrongPct;
    pick.bound = config.autoMaxWrongPct;
    return pick;
}

MatrixCell renderAutoCell(Harness& harness, AccuracyEvaluator& evaluator, std::optional<AutoPick>& pick,
                          std::string& refusal, const std::string& scene, const MatrixOptions& options) {
    if (!pick && refusal.empty()) {
        try {
            pick = resolveAuto(harness, options);
        } catch (const Error& e) {
            if (e.code() != ExitCode::Unsupported) throw;
            refusal = e.what();
        }
    }
    if (!pick) {
        MatrixCell cell;
        cell.technique = AutoResolver::kName;
        cell.scene = scene;
        cell.mode = harness.config().submit;
        cell.unsupported = refusal;
        cell.refusal = MatrixCell::Refusal::Scene;
        return cell;
    }
    MatrixCell cell =
        renderCell(harness, evaluator, AutoResolver::kName, TechniqueSpec::parse(pick->spec), scene, options);
    cell.autoPick = pick;
    cell.autoPick->effects = TechniqueRegistry::create(TechniqueSpec::parse(pick->spec))->info().effects;
    return cell;
}

MatrixCell unsupportedCell(const std::string& technique, const std::string& scene, SubmitMode mode,
                           const std::string& api, const std::string& why, MatrixCell::Refusal refusal) {
    MatrixCell cell;
    cell.technique = technique;
    cell.scene = scene;
    cell.mode = mode;
    cell.api = api;
    cell.unsupported = why;
    cell.refusal = refusal;
    return cell;
}

/// One Vulkan cell: rendered by `vulkan` and judged by `evaluator`, an evaluator of that harness (its own
/// frames at the samples its own G-buffer places), as renderCell judges a GL cell: the same frame of a
/// path, each light's frame rendered again. A validation error fails the cell.
MatrixCell renderVulkanCell(VulkanHarness& vulkan, AccuracyEvaluator& evaluator, const std::string& technique,
                            const std::string& scene, const MatrixOptions& options,
                            const TechniqueSpec* spec = nullptr) {
    MatrixCell cell;
    cell.technique = technique;
    cell.scene = scene;
    cell.mode = vulkan.config().submit;
    cell.api = "vulkan";
    std::unique_ptr<VulkanTechnique> t =
        TechniqueRegistry::createVulkan(spec ? *spec : TechniqueSpec::parse(technique));
    const size_t errorsBefore = vulkan.context().validationErrors();
    if (refusedByDriver(cell, driverRefusal(t->checkCapabilities(vulkan.context())), options)) return cell;
    vulkan.seekPath(0); // a scene in motion starts each cell at rest
    try {
        vulkan.prepare(*t);
    } catch (const Error& e) {
        if (e.code() != ExitCode::Unsupported) throw;
        cell.unsupported = e.what();
        cell.refusal = MatrixCell::Refusal::Scene;
        return cell;
    }
    if (vulkan.moving())
        for (uint64_t f = 0; f < kPathStep; ++f) vulkan.renderFrame(*t);
    vulkan.seekPath(kPathStep);
    vulkan.renderFrame(*t);
    const size_t lights = vulkan.scene().lights.size();
    readImages(vulkan.width(), vulkan.height(), vulkan.readVisibility(), vulkan.readColor(), lights, cell);
    for (size_t l = 0; l < lights; ++l) {
        vulkan.seekPath(kPathStep); // each judged frame is the same frame of the path
        cell.lights.push_back(scoreLight(evaluator.judgeFrame(*t, optionsFor(int(l), options), nullptr),
                                         int(l), vulkan.scene(), options));
    }
    if (vulkan.context().validationErrors() > errorsBefore) {
        const std::vector<std::string> messages = vulkan.takeValidationMessages();
        cell.failure = "the Vulkan validation layer reported an error: " +
                       (messages.empty() ? std::string("(no message kept)") : messages.back());
    }
    return cell;
}

/// -t auto on Vulkan, as `bench --api vulkan -t auto` resolves it: calibrated among the Vulkan forms on
/// the first mode's Vulkan harness (a calibration of its own, kept for the other mode as the GL cells
/// keep theirs), the chosen technique rendered and held to its golden as the GL auto cells are.
MatrixCell vulkanAutoCell(VulkanHarness& vulkan, AccuracyEvaluator& evaluator, std::optional<AutoPick>& pick,
                          std::string& refusal, const std::string& scene, SubmitMode mode,
                          const MatrixOptions& options) {
    if (!pick && refusal.empty()) {
        try {
            pick = resolveAuto(vulkan, options);
        } catch (const Error& e) {
            if (e.code() != ExitCode::Unsupported) throw;
            refusal = e.what();
        }
    }
    if (!pick)
        return unsupportedCell(AutoResolver::kName, scene, mode, "vulkan", refusal,
                               MatrixCell::Refusal::Scene);
    const TechniqueSpec chosen = TechniqueSpec::parse(pick->spec);
    MatrixCell cell = renderVulkanCell(vulkan, evaluator, chosen.name, scene, options, &chosen);
    cell.technique = AutoResolver::kName;
    cell.autoPick = pick;
    cell.autoPick->effects = TechniqueRegistry::createVulkan(chosen)->info().effects;
    return cell;
}

/// One Vulkan cell of the axis: unsupported with the reason where it cannot run, else rendered.
/// `autoPick`, `autoRefusal`: -t auto's Vulkan choice for the scene (vulkanAutoCell).
MatrixCell vulkanCell(VulkanHarness* vulkan, AccuracyEvaluator* evaluator, const std::string& refusal,
                      const std::string& technique, const std::string& scene, SubmitMode mode,
                      const MatrixOptions& options, std::optional<AutoPick>& autoPick,
                      std::string& autoRefusal) {
    if (technique != AutoResolver::kName && !hasForm(technique, Api::Vulkan))
        return unsupportedCell(technique, scene, mode, "vulkan", noFormReason(technique, Api::Vulkan),
                               MatrixCell::Refusal::NoForm);
    if (!vulkan) { // no Vulkan device on this driver at all
        MatrixCell cell = unsupportedCell(technique, scene, mode, "vulkan", "", MatrixCell::Refusal::None);
        refusedByDriver(cell, driverRefusal(refusal), options);
        return cell;
    }
    if (technique == AutoResolver::kName)
        return vulkanAutoCell(*vulkan, *evaluator, autoPick, autoRefusal, scene, mode, options);
    try {
        return renderVulkanCell(*vulkan, *evaluator, technique, scene, options);
    } catch (const std::exception& e) {
        MatrixCell failed = unsupportedCell(technique, scene, mode, "vulkan", "", MatrixCell::Refusal::None);
        failed.failure = e.what();
        return failed;
    }
}

/// The Vulkan axis of one scene (GoldenMatrix::renderScene).
void renderVulkanCells(const std::string& scene, const Scene& loaded, const std::string& camera,
                       const std::vector<std::string>& techniques, const MatrixOptions& options,
                       const MatrixObserver& observer, std::vector<MatrixCell>& cells) {
    std::optional<AutoPick> autoPick; // -t auto's Vulkan choice, resolved on the first mode's harness
    std::string autoRefusal;          // or why nothing qualifies
    for (SubmitMode mode : kVulkanModes) {
        RunConfig config = cellConfig(scene, loaded, camera, mode, options);
        config.api = RunConfig::Api::Vulkan;
        config.vulkan.validation = true;
        std::unique_ptr<VulkanHarness> vulkan;
        std::string refusal;
        try {
            vulkan = std::make_unique<VulkanHarness>(config);
        } catch (const Error& e) {
            if (e.code() != ExitCode::Unsupported) throw;
            refusal = e.what(); // no Vulkan driver at all
        }
        // Each mode's harness judges its own frames (no GL context on the Vulkan axis).
        std::unique_ptr<AccuracyEvaluator> evaluator;
        if (vulkan) evaluator = std::make_unique<AccuracyEvaluator>(*vulkan);
        for (const std::string& technique : techniques)
            addCell(cells, cellName(technique, scene, mode, true), observer, [&] {
                return vulkanCell(vulkan.get(), evaluator.get(), refusal, technique, scene, mode, options,
                                  autoPick, autoRefusal);
            });
    }
}

} // namespace

std::string MatrixCell::judgedAs() const {
    return autoPick ? autoPick->spec.substr(0, autoPick->spec.find(':')) : technique;
}

std::string MatrixCell::name() const {
    return cellName(technique, scene, mode, vulkan());
}

const MatrixCell* GoldenMatrix::goldenCellOf(const std::vector<MatrixCell>& cells, const MatrixCell& cell) {
    auto retained = [&](bool vulkan) -> const MatrixCell* {
        for (const MatrixCell& c : cells)
            if (c.technique == cell.technique && c.scene == cell.scene && c.mode == SubmitMode::Retained &&
                c.vulkan() == vulkan)
                return &c;
        return nullptr;
    };
    const MatrixCell* gl = retained(false);
    if (gl && gl->refusal != MatrixCell::Refusal::NoForm) return gl;
    return gl ? retained(true) : nullptr;
}

std::vector<std::string> GoldenMatrix::builtinScenes() {
    std::vector<std::string> scenes;
    const std::string probe = Paths::findResource("scenes/data/aircraft.json");
    if (probe.empty())
        throw Error("cannot find scenes/data/ (looked in the build and source trees)", ExitCode::Failure);
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(probe).parent_path()))
        if (entry.path().extension() == ".json") scenes.push_back(entry.path().stem().string());
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

std::string GoldenMatrix::cameraFor(const std::string& scene) {
    return cameraFor(SceneLoader::load(scene));
}

std::string GoldenMatrix::cameraFor(const Scene& s) {
    for (const CameraPreset& c : s.cameras)
        if (c.name == "mid") return c.name;
    if (s.cameras.empty()) throw Error("scene '" + s.name + "' has no camera", ExitCode::BadInput);
    return s.cameras.front().name;
}

std::optional<uint32_t> GoldenMatrix::layoutInstances(const Scene& s, const MatrixOptions& options) {
    const size_t total = s.totalTriangles(), layout = s.countLayoutInstances();
    if (total <= options.maxTriangles || layout == 0) return std::nullopt;
    size_t layoutTriangles = 0;
    for (const Instance& i : s.instances)
        if (i.fromLayout && i.mesh < s.meshes.size()) layoutTriangles += s.meshes[i.mesh].triangleCount();
    const size_t placed = total - layoutTriangles;
    const double room = options.maxTriangles > placed ? double(options.maxTriangles - placed) : 0.0;
    const double perInstance = double(layoutTriangles) / double(layout);
    return uint32_t(std::clamp(std::floor(room / perInstance), 1.0, double(layout)));
}

size_t GoldenMatrix::cellsPerScene(const MatrixOptions& options) {
    return techniquesOf(options).size() * (std::size(kAllSubmitModes) + std::size(kVulkanModes));
}

std::vector<MatrixCell> GoldenMatrix::renderScene(const std::string& scene, const MatrixOptions& options,
                                                  const MatrixObserver& observer) {
    const std::vector<std::string> techniques = techniquesOf(options);
    const Scene loaded = SceneLoader::load(scene); // once, not once per mode
    const std::string camera = cameraFor(loaded);
    std::vector<MatrixCell> cells;
    std::optional<AutoPick> pick; // -t auto's choice, resolved on the retained harness (the first)
    std::string refusal;          // or why nothing qualifies
    const bool glForms = anyGlForm(techniques); // else no GL harness: every GL cell is a NoForm cell
    for (SubmitMode mode : modesRetainedFirst()) {
        const RunConfig config = cellConfig(scene, loaded, camera, mode, options);
        std::unique_ptr<Harness> harnessOwner = glForms ? std::make_unique<Harness>(config) : nullptr;
        std::unique_ptr<AccuracyEvaluator> evaluatorOwner =
            glForms ? std::make_unique<AccuracyEvaluator>(*harnessOwner) : nullptr;
        for (const std::string& technique : techniques)
            addCell(cells, cellName(technique, scene, mode, false), observer, [&] {
                if (technique != AutoResolver::kName && !hasForm(technique, Api::GL))
                    return unsupportedCell(technique, scene, mode, "gl", noFormReason(technique, Api::GL),
                                           MatrixCell::Refusal::NoForm);
                Harness& harness = *harnessOwner;
                AccuracyEvaluator& evaluator = *evaluatorOwner;
                try {
                    if (technique == AutoResolver::kName)
                        return renderAutoCell(harness, evaluator, pick, refusal, scene, options);
                    return renderCell(harness, evaluator, technique, TechniqueSpec::parse(technique), scene,
                                      options);
                } catch (const std::exception& e) {
                    MatrixCell failed;
                    failed.technique = technique;
                    failed.scene = scene;
                    failed.mode = mode;
                    failed.failure = e.what();
                    return failed;
                }
            });
    }
    renderVulkanCells(scene, loaded, camera, techniques, options, observer, cells);
    return cells;
}

} // namespace sb
