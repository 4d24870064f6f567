#include "bench/lib/select/Calibration.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <ostream>
#include <unistd.h>

#include "bench/lib/harness/VulkanHarness.h"
#include "bench/lib/measure/AccuracyEvaluator.h"
#include "bench/lib/output/CsvNumber.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/rows/Environment.h"
#include "core/Error.h"
#include "core/Paths.h"
#include "core/Strings.h"
#include "registry/TechniqueRegistry.h"
#include "techniques/PointLightRefusal.h"

namespace sb {

namespace {

/// Not candidates: the judge itself, and workloads that are not shadow techniques.
bool isCandidate(const std::string& name) {
    return name != "reference" && name != "synthetic";
}

/// Misclassified samples (lit against shadowed, at 0.5) over the evaluated samples the reference
/// shadows, in %: a technique that draws no shadow scores 100 whatever the image size, where a share of
/// all samples would call it nearly right whenever the shadow is small.
double misplacedShadowPct(const AccuracyEvaluator::Sample& s) {
    uint64_t shadowed = 0, wrong = 0;
    for (size_t i = 0; i < s.mask.size(); ++i) {
        if (!s.mask[i]) continue;
        const bool reference = s.reference[i] < 0.5f, technique = s.technique[i] < 0.5f;
        shadowed += reference;
        wrong += reference != technique;
    }
    return 100.0 * double(wrong) / double(std::max<uint64_t>(1, shadowed));
}

/// The configurations of technique `name` that are candidates on `scene`: its defaults, except where
/// the scene has a point light that casts shadows and PointLightRefusal names configurations of `name`
/// that shade it (hybrid with an omni map as its cast part: its default cast part, shadowmap, refuses
/// such a light). Those are tried instead, under the names a user gives them.
std::vector<std::string> configurationsOf(const std::string& name, const Scene& scene) {
    std::vector<std::string> variants;
    if (PointLightRefusal::sceneHasOne(scene))
        for (const std::string& spec : PointLightRefusal::omniHybrids())
            if (TechniqueSpec::parse(spec).name == name) variants.push_back(spec);
    return variants.empty() ? std::vector<std::string>{name} : variants;
}

/// One candidate being measured: its technique, prepared on the harness, and what it measured.
struct Trial {
    size_t candidate = 0;                 ///< index into the candidates
    std::unique_ptr<Technique> technique; ///< the form of the harness's API
};

double median(std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
    return v[v.size() / 2];
}

/// The worst light's misplaced share of the shadow.
double judge(MeasuredHarness& harness, Technique& technique, AccuracyEvaluator& evaluator) {
    AccuracyOptions accuracy;
    accuracy.stability = false;
    double worst = 0.0;
    for (accuracy.light = 0; accuracy.light < int(harness.scene().lights.size()); ++accuracy.light) {
        harness.seekPath(0); // a scene in motion is judged at the start of its path
        worst = std::max(worst, misplacedShadowPct(evaluator.judgeFrame(technique, accuracy, nullptr)));
    }
    return worst;
}

/// Vertex plus fragment shader invocations of one census frame (-1 where the context cannot count).
double exactWork(MeasuredHarness& harness, Technique& technique) {
    const FrameLoads loads = harness.measureLoads(technique);
    if (!loads.pipeline) return -1.0;
    return double(loads.pipeline->vertexShaderInvocations + loads.pipeline->fragmentShaderInvocations);
}

/// Times the trials in interleaved rounds (one frame of each per round, after their warm-up), so load
/// that comes and goes falls on every candidate alike, then takes each one's exact work and error.
void measureInterleaved(MeasuredHarness& harness, std::vector<Trial>& trials,
                        std::vector<AutoCandidate>& out, const CalibrationOptions& options,
                        const std::string& batch) {
    for (Trial& t : trials)
        for (int i = 0; i < options.warmup; ++i) harness.renderFrame(*t.technique);
    for (int r = 0; r < std::max(1, options.frames); ++r)
        for (Trial& t : trials) out[t.candidate].rounds.push_back(harness.renderFrame(*t.technique).wallMs);
    std::unique_ptr<AccuracyEvaluator> evaluator;
    for (Trial& t : trials) {
        AutoCandidate& c = out[t.candidate];
        c.measured = true;
        c.costMs = median(c.rounds);
        c.batch = batch;
        c.work = exactWork(harness, *t.technique);
        if (!evaluator) evaluator = std::make_unique<AccuracyEvaluator>(harness);
        c.wrongPct = judge(harness, *t.technique, *evaluator);
    }
}

std::string joinRounds(const std::vector<double>& rounds) {
    std::string out;
    for (double r : rounds) out += (out.empty() ? "" : ";") + csvNumber(r);
    return out;
}

std::vector<double> parseRounds(const std::string& text) {
    std::vector<double> out;
    for (size_t start = 0; start < text.size();) {
        const size_t end = std::min(text.find(';', start), text.size());
        out.push_back(std::strtod(text.substr(start, end - start).c_str(), nullptr));
        start = end + 1;
    }
    return out;
}

/// Whether `row` is `key`'s. The API is part of every key: GL's keys and rows written before the cache
/// knew APIs have no `api` column and mean GL, so a Vulkan row never answers for GL nor the other way.
bool sameKey(const CsvTable& table, const std::vector<std::string>& row, const CsvRow& key) {
    bool keyHasApi = false;
    for (const auto& [column, value] : key) {
        keyHasApi = keyHasApi || column == "api";
        if (table.cell(row, column) != value) return false;
    }
    const std::string rowApi = table.cell(row, "api");
    return keyHasApi || rowApi.empty() || rowApi == "gl";
}

/// The last cached row of `key`, if any.
const std::vector<std::string>* cached(const CsvTable& table, const CsvRow& key) {
    const std::vector<std::string>* found = nullptr;
    for (const auto& row : table.rows)
        if (sameKey(table, row, key)) found = &row;
    return found;
}

AutoCandidate fromCache(const CsvTable& table, const std::vector<std::string>& row, AutoCandidate c) {
    c.measured = table.cell(row, "status") == "ok";
    c.refusal = table.cell(row, "refusal");
    if (c.measured) {
        c.costMs = std::strtod(table.cell(row, "wall_ms").c_str(), nullptr);
        c.wrongPct = std::strtod(table.cell(row, "wrong_pct").c_str(), nullptr);
        // Written by calibrations since the interleaved rounds; a hand-written or older row has none.
        c.rounds = parseRounds(table.cell(row, "wall_rounds"));
        c.batch = table.cell(row, "batch");
        const std::string work = table.cell(row, "work");
        c.work = work.empty() ? -1.0 : std::strtod(work.c_str(), nullptr);
    }
    return c;
}

/// The seed's file: `given` as it is when it exists (or is absolute), else as bench finds its data.
std::string seedFile(const std::string& given) {
    std::error_code ec;
    if (std::filesystem::exists(given, ec) || std::filesystem::path(given).is_absolute()) return given;
    const std::string found = Paths::findResource(given);
    return found.empty() ? given : found;
}

/// The seed's rows (none for ""); a seed named but missing is bad input, not an empty calibration.
CsvTable readSeed(const std::string& given) {
    if (given.empty()) return {};
    const std::string path = seedFile(given);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw Error("--calibration-seed " + given + ": no such file", ExitCode::BadInput);
    return CsvWriter::read(path);
}

CsvRow cacheRow(const CsvRow& key, const AutoCandidate& c) {
    CsvRow row = key;
    row.emplace_back("status", c.measured ? "ok" : "refused");
    row.emplace_back("refusal", c.refusal);
    row.emplace_back("wall_ms", c.measured ? csvNumber(c.costMs) : "");
    row.emplace_back("wrong_pct", c.measured ? csvNumber(c.wrongPct) : "");
    row.emplace_back("wall_rounds", c.measured ? joinRounds(c.rounds) : "");
    row.emplace_back("batch", c.batch);
    row.emplace_back("work", c.measured && c.work >= 0.0 ? csvNumber(c.work) : "");
    row.emplace_back("measured_at", Environment::nowIso8601());
    return row;
}

} // namespace

std::string Calibration::defaultCachePath() {
    const char* xdg = std::getenv("XDG_CACHE_HOME");
    const char* home = std::getenv("HOME");
    std::error_code ignored;
    std::filesystem::path dir = xdg && *xdg ? std::filesystem::path(xdg) / "shadowbench"
                                : home && *home
                                    ? std::filesystem::path(home) / ".cache" / "shadowbench"
                                    : std::filesystem::temp_directory_path(ignored) / "shadowbench";
    return (dir / "auto-calibration.csv").string();
}

CsvRow Calibration::keyColumns(const MeasuredHarness& harness, const std::string& spec) {
    const RunConfig& c = harness.config();
    CsvRow key;
    if (harness.api() == Api::Vulkan) {
        // The device and its driver in the columns GL fills with GL_RENDERER and GL_VERSION, and the API.
        const VulkanDeviceInfo& device = static_cast<const VulkanHarness&>(harness).context().info();
        key = {{"api", "vulkan"},
               {"renderer", device.name},
               {"gl_version", "Vulkan " + device.apiVersion + " " + device.driver}};
    } else {
        const Harness& gl = static_cast<const Harness&>(harness);
        key = {{"renderer", gl.context().renderer}, {"gl_version", gl.context().version}};
    }
    key.insert(key.end(), {{"scene", harness.scene().name},
                           {"scene_hash", harness.contentHash()},
                           {"width", std::to_string(c.width)},
                           {"height", std::to_string(c.height)},
                           {"camera", c.camera},
                           {"submit", submitModeName(c.submit)},
                           {"candidate", spec}});
    return key;
}

std::vector<AutoCandidate> Calibration::candidates(MeasuredHarness& harness, const CalibrationOptions& options,
                                                   std::ostream& log) {
    const std::string path = options.cachePath.empty() ? defaultCachePath() : options.cachePath;
    const CsvTable seed = readSeed(options.seedPath);
    CsvTable table;
    if (std::filesystem::exists(path)) table = CsvWriter::read(path);
    std::vector<AutoCandidate> out;
    std::vector<CsvRow> keys;  ///< per candidate
    std::vector<bool> measure; ///< per candidate: not (usefully) in the cache
    std::vector<Trial> trials;
    size_t fromSeed = 0, fromFile = 0;
    const Api api = harness.api();
    std::vector<std::string> configurations, withoutForm;
    for (const std::string& name : TechniqueRegistry::names()) {
        if (!isCandidate(name)) continue;
        if (!TechniqueRegistry::has(name, api)) { // measured on the API it runs on, or not at all
            withoutForm.push_back(name);
            continue;
        }
        for (const std::string& spec : configurationsOf(name, harness.scene()))
            configurations.push_back(spec);
    }
    if (!withoutForm.empty())
        log << "auto: skipped (no " << (api == Api::Vulkan ? "Vulkan" : "GL")
            << " form): " << join(withoutForm, ", ") << "\n";
    for (const std::string& given : configurations) {
        const TechniqueSpec parsed = TechniqueSpec::parse(given);
        std::unique_ptr<Technique> technique = TechniqueRegistry::create(parsed, api);
        AutoCandidate c;
        // A technique without properties (none) is its bare name: "none:" does not parse back.
        const std::string properties = technique->properties().toString();
        c.spec = properties.empty() ? parsed.name : parsed.name + ":" + properties;
        c.variant = parsed.properties.empty() ? "" : given;
        c.effects = technique->info().effects;
        keys.push_back(keyColumns(harness, c.spec));
        if (const auto* row = options.refresh ? nullptr : cached(seed, keys.back())) {
            out.push_back(fromCache(seed, *row, c));
            measure.push_back(false);
            ++fromSeed;
            continue;
        }
        if (const auto* row = options.refresh ? nullptr : cached(table, keys.back())) {
            out.push_back(fromCache(table, *row, c));
            measure.push_back(false);
            ++fromFile;
            continue;
        }
        measure.push_back(true);
        try {
            harness.seekPath(0);
            harness.prepare(*technique);
            trials.push_back({out.size(), std::move(technique)});
        } catch (const Error& e) {
            if (e.code() == ExitCode::Failure) throw; // a broken run is not a refusal
            c.refusal = e.what();
        }
        out.push_back(c);
    }
    const std::string batch = Environment::nowIso8601() + "#" + std::to_string(::getpid());
    if (!trials.empty()) measureInterleaved(harness, trials, out, options, batch);
    std::vector<CsvRow> fresh;
    for (size_t i = 0; i < out.size(); ++i)
        if (measure[i]) fresh.push_back(cacheRow(keys[i], out[i]));
    log << "auto: " << out.size() << " candidates, ";
    if (!options.seedPath.empty()) log << fromSeed << " from the seed " << options.seedPath << ", ";
    log << fromFile << " from " << path << ", " << fresh.size() << " measured now (" << options.frames
        << " interleaved rounds of one frame each, exact work, judged against the reference)\n";
    if (!fresh.empty()) {
        std::error_code ignored;
        std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ignored);
        CsvWriter::appendRows(path, fresh);
    }
    return out;
}

} // namespace sb
