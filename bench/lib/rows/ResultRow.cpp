#include "bench/lib/rows/ResultRow.h"

#include <array>

#include "bench/lib/output/CsvNumber.h"
#include "bench/lib/output/ResultColumns.h"
#include "core/DriverTable.h"
#include "core/Injection.h"
#include "gl/backends/BackendRegistry.h"
#include "scenes/Motion.h"
#include "techniques/EffectCoverage.h"

namespace sb {

namespace {

/// The seven statistics columns of one series, in the order addStats writes them.
using StatsColumns = std::array<const char*, 7>;
constexpr StatsColumns kWallStats = {col::kWallMsMedian, col::kWallMsP5,     col::kWallMsP95, col::kWallMsP99,
                                     col::kWallMsMean,   col::kWallMsStddev, col::kWallMsMad};
constexpr StatsColumns kCpuSubmitStats = {
    col::kCpuSubmitMsMedian, col::kCpuSubmitMsP5,     col::kCpuSubmitMsP95, col::kCpuSubmitMsP99,
    col::kCpuSubmitMsMean,   col::kCpuSubmitMsStddev, col::kCpuSubmitMsMad};

void addStats(CsvRow& row, const StatsColumns& names, const Statistics& s) {
    const double values[] = {s.median, s.p5, s.p95, s.p99, s.mean, s.stddev, s.mad};
    for (size_t i = 0; i < names.size(); ++i) row.emplace_back(names[i], csvNumber(values[i]));
}

/// "directional+point": a light that casts no shadow is marked ("point:unshadowed").
std::string lightsText(const Scene& scene) {
    std::string out;
    for (const Light& l : scene.lights) {
        if (!out.empty()) out += '+';
        out += lightTypeName(l.type);
        if (!l.castsShadows) out += ":unshadowed";
    }
    return out.empty() ? "none" : out;
}

/// "depth: no light casts a shadow; blur: blur 0"; "" when the frame ran every declared pass.
std::string skippedText(const SkippedPasses& skipped) {
    std::string out;
    for (const auto& [pass, reason] : skipped) out += (out.empty() ? "" : "; ") + pass + ": " + reason;
    return out;
}

/// The census frame's loads; the pipeline's cells stay empty where the context cannot count them.
void addLoads(CsvRow& row, const FrameLoads& loads) {
    const std::optional<PipelineCounts>& p = loads.pipeline;
    auto count = [&](uint64_t PipelineCounts::*field) { return p ? std::to_string((*p).*field) : ""; };
    row.emplace_back(col::kLoadGlCalls, std::to_string(loads.submitted.glCalls));
    row.emplace_back(col::kLoadVertices, count(&PipelineCounts::vertexShaderInvocations));
    row.emplace_back(col::kLoadPrimitives, count(&PipelineCounts::primitivesSubmitted));
    row.emplace_back(col::kLoadClippedPrimitives, count(&PipelineCounts::clippingOutputPrimitives));
    row.emplace_back(col::kLoadFragments, count(&PipelineCounts::fragmentShaderInvocations));
}

/// The census frame's work pass by pass (bench/lib/harness/WorkCensus.h), the exact layer of the perf gate:
/// `work_<pass>_<counter>`. Pipeline cells stay empty where the context cannot count them.
void addPassWork(CsvRow& row, const FrameWork& passes) {
    for (const auto& [pass, w] : passes) {
        const std::optional<PipelineCounts>& p = w.pipeline;
        auto count = [&](uint64_t PipelineCounts::*field) { return p ? std::to_string((*p).*field) : ""; };
        row.emplace_back(col::member(col::kWorkGlCalls, pass), std::to_string(w.submitted.glCalls));
        row.emplace_back(col::member(col::kWorkDraws, pass), std::to_string(w.submitted.drawCalls));
        row.emplace_back(col::member(col::kWorkTriangles, pass), std::to_string(w.submitted.triangles));
        row.emplace_back(col::member(col::kWorkVertices, pass),
                         count(&PipelineCounts::vertexShaderInvocations));
        row.emplace_back(col::member(col::kWorkPrimitives, pass),
                         count(&PipelineCounts::primitivesSubmitted));
        row.emplace_back(col::member(col::kWorkClippedPrimitives, pass),
                         count(&PipelineCounts::clippingOutputPrimitives));
        row.emplace_back(col::member(col::kWorkFragments, pass),
                         count(&PipelineCounts::fragmentShaderInvocations));
    }
}

} // namespace

CsvRow ResultRow::effectColumns(const EffectCoverage& coverage) {
    return {{col::kEffectsRequested, effectMaskToString(coverage.requested)},
            {col::kEffectsDelivered, effectMaskToString(coverage.delivered)},
            {col::kEffectsMissing, effectMaskToString(coverage.missing)}};
}

CsvRow ResultRow::build(const MeasuredHarness& h, const RunResult& r, const Environment& env) {
    return build(h.rowSource(), r, env);
}

CsvRow ResultRow::build(const RowSource& h, const RunResult& r, const Environment& env) {
    const RunConfig& c = h.config;
    const Scene& scene = h.scene;
    const TimerVerdict& v = h.verdict;
    const EffectCoverage coverage = EffectCoverage::of(scene.effects, r.effectsProduced);
    CsvRow row{
        {col::kTimestamp, env.timestamp},
        {col::kGitCommit, env.gitCommit},
        {col::kStatus, col::kStatusOk},
        {col::kApi, h.api},
        {col::kApiVersion, h.apiVersion},
        {col::kRenderer, h.renderer},
        {col::kGlVersion, h.glVersion},
        {col::kGlVendor, h.vendor},
        {col::kDriver, DriverTable::current()},
        {col::kDriverVersion, h.driverVersion},
        {col::kBackend, h.backend},
        {col::kDevice, h.device},
        {col::kCpuModel, env.cpuModel},
        {col::kHwThreads, std::to_string(env.hardwareThreads)},
        {col::kLpNumThreads, env.lpNumThreads},
    };
    const CsvRow place = env.placeColumns();
    row.insert(row.end(), place.begin(), place.end());
    row.insert(row.end(), {
                              {col::kScene, scene.name},
                              {col::kSceneHash, h.contentHash},
                              {col::kSceneTriangles, std::to_string(scene.totalTriangles())},
                              {col::kTechnique, r.technique},
                              {col::kProperties, r.properties},
                              {col::kPermutation, r.permutation},
                          });
    for (auto& column : effectColumns(coverage)) row.push_back(std::move(column));
    row.emplace_back(col::kPassesSkipped, skippedText(r.loads.skipped));
    CsvRow rest{
        {col::kInstances, std::to_string(scene.countLayoutInstances())},
        {col::kScale, csvNumber(c.sceneOptions.scale)},
        {col::kTessellation,
         c.sceneOptions.tessellation ? std::to_string(*c.sceneOptions.tessellation) : "default"},
        {col::kTessFactor, csvNumber(c.sceneOptions.tessellationFactor)},
        {col::kSeed, c.sceneOptions.seed ? std::to_string(*c.sceneOptions.seed) : "default"},
        {col::kModel, c.sceneOptions.modelPath},
        {col::kSubmit, submitModeName(c.submit)},
        {col::kBackFaces, backFacesName(c.backFaces)},
        {col::kLighting, lightingRateName(scene.lighting)},
        {col::kCamera, c.camera},
        {col::kWidth, std::to_string(c.width)},
        {col::kHeight, std::to_string(c.height)},
        {col::kLights, lightsText(scene)},
        {col::kMotion, scene.motion ? scene.motion->describe() : ""},
        {col::kPathFrames, scene.motion ? std::to_string(scene.motion->frames) : ""},
        {col::kPathTime, !scene.motion ? ""
                         : h.moving    ? "moving"
                                       : csvNumber(c.pathTime)},
        {col::kFrames, std::to_string(r.wall.n)},
        {col::kWarmup, std::to_string(c.warmup)},
        {col::kSetupMs, csvNumber(r.setupMs)},
    };
    for (auto& column : rest) row.push_back(std::move(column));
    addStats(row, kWallStats, r.wall);
    addStats(row, kCpuSubmitStats, r.cpuSubmit);
    for (const auto& [pass, stats] : r.cpuPass)
        row.emplace_back(col::member(col::kCpuPassMsMedian, pass), stats.n ? csvNumber(stats.median) : "");
    row.emplace_back(col::kMotionMsMedian, h.moving ? csvNumber(r.motion.median) : "");
    row.emplace_back(col::kMotionMsP95, h.moving ? csvNumber(r.motion.p95) : "");
    row.emplace_back(col::kFpsMedian, csvNumber(r.wall.median > 0 ? 1000.0 / r.wall.median : 0.0));
    row.emplace_back(col::kTimerVerdict, v.label());
    row.emplace_back(col::kTimerReason, v.reason);
    bool trusted = v.checked && v.trusted;
    row.emplace_back(col::kGpuMsMedian, trusted && r.gpuTotal.n ? csvNumber(r.gpuTotal.median) : "");
    for (const auto& [pass, stats] : r.gpuPass)
        row.emplace_back(col::member(col::kGpuPassMsMedian, pass),
                         trusted && stats.n ? csvNumber(stats.median) : "");
    for (const auto& [name, value] : r.counters)
        row.emplace_back(col::member(col::kCounter, name), csvNumber(value));
    addLoads(row, r.loads);
    addPassWork(row, r.loads.passes);
    // A row measured with a deliberate regression switched on says so (core/Injection.h).
    if (!injectionsText().empty()) row.emplace_back(col::kInjected, injectionsText());
    return row;
}

} // namespace sb
