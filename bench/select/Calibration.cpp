#include "bench/select/Calibration.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <ostream>

#include "bench/output/CsvNumber.h"
#include "bench/output/CsvWriter.h"
#include "bench/run/AccuracyEvaluator.h"
#include "bench/run/Environment.h"
#include "core/Error.h"
#include "techniques/TechniqueRegistry.h"

namespace sb {

namespace {

/// Not candidates: the judge itself, and workloads that are not shadow techniques.
bool isCandidate(const std::string& name) {
    return name != "reference" && name != "synthetic";
}

struct Measured {
    double costMs = 0.0, wrongPct = 0.0;
};

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

Measured measureOne(Harness& harness, Technique& technique, AccuracyEvaluator& evaluator,
                    const CalibrationOptions& options) {
    harness.prepare(technique);
    for (int i = 0; i < options.warmup; ++i) harness.renderFrame(technique);
    std::vector<double> wall;
    for (int i = 0; i < std::max(1, options.frames); ++i)
        wall.push_back(harness.renderFrame(technique).wallMs);
    std::nth_element(wall.begin(), wall.begin() + long(wall.size() / 2), wall.end());
    Measured m;
    m.costMs = wall[wall.size() / 2];
    AccuracyOptions accuracy;
    accuracy.stability = false;
    const int lights = std::max<int>(1, int(harness.scene().lights.size()));
    for (accuracy.light = 0; accuracy.light < lights && accuracy.light < int(harness.scene().lights.size());
         ++accuracy.light)
        m.wrongPct =
            std::max(m.wrongPct, misplacedShadowPct(evaluator.judgeFrame(technique, accuracy, nullptr)));
    return m;
}

bool sameKey(const CsvTable& table, const std::vector<std::string>& row, const CsvRow& key) {
    for (const auto& [column, value] : key)
        if (table.cell(row, column) != value) return false;
    return true;
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
    }
    return c;
}

CsvRow cacheRow(const CsvRow& key, const AutoCandidate& c) {
    CsvRow row = key;
    row.emplace_back("status", c.measured ? "ok" : "refused");
    row.emplace_back("refusal", c.refusal);
    row.emplace_back("wall_ms", c.measured ? csvNumber(c.costMs) : "");
    row.emplace_back("wrong_pct", c.measured ? csvNumber(c.wrongPct) : "");
    row.emplace_back("measured_at", Environment::nowIso8601());
    return row;
}

} // namespace

std::string Calibration::defaultCachePath() {
    const char* xdg = std::getenv("XDG_CACHE_HOME");
    const char* home = std::getenv("HOME");
    std::filesystem::path dir = xdg && *xdg     ? std::filesystem::path(xdg) / "shadowbench"
                                : home && *home ? std::filesystem::path(home) / ".cache" / "shadowbench"
                                                : std::filesystem::path(".");
    return (dir / "auto-calibration.csv").string();
}

CsvRow Calibration::keyColumns(const Harness& harness, const std::string& spec) {
    const RunConfig& c = harness.config();
    return {{"renderer", harness.context().renderer},
            {"gl_version", harness.context().version},
            {"scene", harness.scene().name},
            {"scene_hash", harness.contentHash()},
            {"width", std::to_string(c.width)},
            {"height", std::to_string(c.height)},
            {"camera", c.camera},
            {"submit", submitModeName(c.submit)},
            {"candidate", spec}};
}

std::vector<AutoCandidate> Calibration::candidates(Harness& harness, const CalibrationOptions& options,
                                                   std::ostream& log) {
    const std::string path = options.cachePath.empty() ? defaultCachePath() : options.cachePath;
    CsvTable table;
    if (std::filesystem::exists(path)) table = CsvWriter::read(path);
    std::vector<AutoCandidate> out;
    std::vector<CsvRow> fresh;
    std::unique_ptr<AccuracyEvaluator> evaluator;
    size_t fromFile = 0;
    for (const std::string& name : TechniqueRegistry::names()) {
        if (!isCandidate(name)) continue;
        std::unique_ptr<Technique> technique = TechniqueRegistry::create(name);
        AutoCandidate c;
        // A technique without properties (none) is its bare name: "none:" does not parse back.
        const std::string properties = technique->properties().toString();
        c.spec = properties.empty() ? name : name + ":" + properties;
        c.effects = technique->info().effects;
        const CsvRow key = keyColumns(harness, c.spec);
        if (const auto* row = options.refresh ? nullptr : cached(table, key)) {
            out.push_back(fromCache(table, *row, c));
            ++fromFile;
            continue;
        }
        if (!evaluator) evaluator = std::make_unique<AccuracyEvaluator>(harness);
        try {
            const Measured m = measureOne(harness, *technique, *evaluator, options);
            c.measured = true;
            c.costMs = m.costMs;
            c.wrongPct = m.wrongPct;
        } catch (const Error& e) {
            if (e.code() == ExitCode::Failure) throw; // a broken run is not a refusal
            c.refusal = e.what();
        }
        fresh.push_back(cacheRow(key, c));
        out.push_back(c);
    }
    log << "auto: " << out.size() << " candidates, " << fromFile << " from " << path << ", " << fresh.size()
        << " measured now (" << options.frames << " frames each, judged against the reference)\n";
    if (!fresh.empty()) {
        std::error_code ignored;
        std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ignored);
        CsvWriter::appendRows(path, fresh);
    }
    return out;
}

} // namespace sb
