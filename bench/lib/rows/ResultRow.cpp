#include "bench/lib/rows/ResultRow.h"

#include "bench/lib/output/CsvNumber.h"
#include "core/Injection.h"
#include "gl/backends/BackendRegistry.h"
#include "scenes/Motion.h"
#include "techniques/EffectCoverage.h"

namespace sb {

namespace {

void addStats(CsvRow& row, const std::string& prefix, const Statistics& s) {
    row.emplace_back(prefix + "_median", csvNumber(s.median));
    row.emplace_back(prefix + "_p5", csvNumber(s.p5));
    row.emplace_back(prefix + "_p95", csvNumber(s.p95));
    row.emplace_back(prefix + "_p99", csvNumber(s.p99));
    row.emplace_back(prefix + "_mean", csvNumber(s.mean));
    row.emplace_back(prefix + "_stddev", csvNumber(s.stddev));
    row.emplace_back(prefix + "_mad", csvNumber(s.mad));
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
    row.emplace_back("load_gl_calls", std::to_string(loads.submitted.glCalls));
    row.emplace_back("load_vertices", count(&PipelineCounts::vertexShaderInvocations));
    row.emplace_back("load_primitives", count(&PipelineCounts::primitivesSubmitted));
    row.emplace_back("load_clipped_primitives", count(&PipelineCounts::clippingOutputPrimitives));
    row.emplace_back("load_fragments", count(&PipelineCounts::fragmentShaderInvocations));
}

/// The census frame's work pass by pass (bench/lib/harness/WorkCensus.h), the exact layer of the perf gate:
/// `work_<pass>_<counter>`. Pipeline cells stay empty where the context cannot count them.
void addPassWork(CsvRow& row, const FrameWork& passes) {
    for (const auto& [pass, w] : passes) {
        const std::string prefix = "work_" + pass + "_";
        const std::optional<PipelineCounts>& p = w.pipeline;
        auto count = [&](uint64_t PipelineCounts::*field) { return p ? std::to_string((*p).*field) : ""; };
        row.emplace_back(prefix + "gl_calls", std::to_string(w.submitted.glCalls));
        row.emplace_back(prefix + "draws", std::to_string(w.submitted.drawCalls));
        row.emplace_back(prefix + "triangles", std::to_string(w.submitted.triangles));
        row.emplace_back(prefix + "vertices", count(&PipelineCounts::vertexShaderInvocations));
        row.emplace_back(prefix + "primitives", count(&PipelineCounts::primitivesSubmitted));
        row.emplace_back(prefix + "clipped_primitives", count(&PipelineCounts::clippingOutputPrimitives));
        row.emplace_back(prefix + "fragments", count(&PipelineCounts::fragmentShaderInvocations));
    }
}

} // namespace

CsvRow ResultRow::effectColumns(const EffectCoverage& coverage) {
    return {{"effects_requested", effectMaskToString(coverage.requested)},
            {"effects_delivered", effectMaskToString(coverage.delivered)},
            {"effects_missing", effectMaskToString(coverage.missing)}};
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
        {"timestamp", env.timestamp},
        {"git_commit", env.gitCommit},
        {"status", "ok"},
        {"api", h.api},
        {"api_version", h.apiVersion},
        {"renderer", h.renderer},
        {"gl_version", h.glVersion},
        {"gl_vendor", h.vendor},
        {"backend", h.backend},
        {"device", h.device},
        {"cpu_model", env.cpuModel},
        {"hw_threads", std::to_string(env.hardwareThreads)},
        {"lp_num_threads", env.lpNumThreads},
        {"scene", scene.name},
        {"scene_hash", h.contentHash},
        {"scene_triangles", std::to_string(scene.totalTriangles())},
        {"technique", r.technique},
        {"properties", r.properties},
        {"permutation", r.permutation},
    };
    for (auto& column : effectColumns(coverage)) row.push_back(std::move(column));
    row.emplace_back("passes_skipped", skippedText(r.loads.skipped));
    CsvRow rest{
        {"instances", std::to_string(scene.countLayoutInstances())},
        {"scale", csvNumber(c.sceneOptions.scale)},
        {"tessellation",
         c.sceneOptions.tessellation ? std::to_string(*c.sceneOptions.tessellation) : "default"},
        {"tess_factor", csvNumber(c.sceneOptions.tessellationFactor)},
        {"seed", c.sceneOptions.seed ? std::to_string(*c.sceneOptions.seed) : "default"},
        {"model", c.sceneOptions.modelPath},
        {"submit", submitModeName(c.submit)},
        {"camera", c.camera},
        {"width", std::to_string(c.width)},
        {"height", std::to_string(c.height)},
        {"lights", lightsText(scene)},
        {"motion", scene.motion ? scene.motion->describe() : ""},
        {"path_frames", scene.motion ? std::to_string(scene.motion->frames) : ""},
        {"path_time", !scene.motion ? ""
                      : h.moving    ? "moving"
                                    : csvNumber(c.pathTime)},
        {"frames", std::to_string(r.wall.n)},
        {"warmup", std::to_string(c.warmup)},
        {"setup_ms", csvNumber(r.setupMs)},
    };
    for (auto& column : rest) row.push_back(std::move(column));
    addStats(row, "wall_ms", r.wall);
    addStats(row, "cpu_submit_ms", r.cpuSubmit);
    row.emplace_back("motion_ms_median", h.moving ? csvNumber(r.motion.median) : "");
    row.emplace_back("motion_ms_p95", h.moving ? csvNumber(r.motion.p95) : "");
    row.emplace_back("fps_median", csvNumber(r.wall.median > 0 ? 1000.0 / r.wall.median : 0.0));
    row.emplace_back("timer_verdict", v.label());
    row.emplace_back("timer_reason", v.reason);
    bool trusted = v.checked && v.trusted;
    row.emplace_back("gpu_ms_median", trusted && r.gpuTotal.n ? csvNumber(r.gpuTotal.median) : "");
    for (const auto& [pass, stats] : r.gpuPass)
        row.emplace_back("gpu_" + pass + "_ms_median", trusted && stats.n ? csvNumber(stats.median) : "");
    for (const auto& [name, value] : r.counters) row.emplace_back("counter_" + name, csvNumber(value));
    addLoads(row, r.loads);
    addPassWork(row, r.loads.passes);
    // A row measured with a deliberate regression switched on says so (core/Injection.h).
    if (!injectionsText().empty()) row.emplace_back("injected", injectionsText());
    return row;
}

} // namespace sb
