#include "bench/run/ConsoleReport.h"

#include "bench/output/TextColumns.h"
#include "core/Strings.h"

#include <cstdio>
#include <ostream>
#include <string>

#include "gl/backends/BackendRegistry.h"
#include "scenes/SceneLoader.h"
#include "techniques/TechniqueRegistry.h"

namespace sb {

namespace {
std::string fmt(const char* f, double v) {
    return formatNumber(f, v);
}

std::string pad(std::string s, size_t w) {
    return padRight(std::move(s), w);
}

std::string effectsText(EffectMask m) {
    return m ? effectMaskToString(m) : "(no shadows)";
}
} // namespace

void ConsoleReport::printHeader(std::ostream& os, const Harness& h) {
    const Context& c = h.context();
    const RunConfig& cfg = h.config();
    size_t layout = 0;
    for (const Instance& i : h.scene().instances) layout += i.fromLayout ? 1 : 0;
    os << "backend   " << backendName(c.backend()) << (c.deviceName.empty() ? "" : " (" + c.deviceName + ")")
       << "\n"
       << "renderer  " << c.renderer << "\n"
       << "GL        " << c.version << "\n"
       << "scene     " << h.scene().name << ": " << layout << " instances, scale " << cfg.sceneOptions.scale
       << ", " << h.scene().totalTriangles() << " triangles, camera " << cfg.camera << ", " << cfg.width
       << "x" << cfg.height << ", submit " << submitModeName(cfg.submit) << "\n"
       << "frames    " << (cfg.seconds > 0 ? fmt("%.1f s", cfg.seconds) : std::to_string(cfg.frames))
       << " after " << cfg.warmup << " warm-up\n";
}

void ConsoleReport::printTimerVerdict(std::ostream& os, const TimerVerdict& v) {
    os << "GPU timer " << v.label();
    if (!v.reason.empty()) os << ": " << v.reason;
    if (v.checked && !v.trusted)
        os << "\n          -> GPU times are not reported; use wall and CPU-submit times";
    os << "\n";
}

void ConsoleReport::printTable(std::ostream& os, const Harness& h, const std::vector<RunResult>& results) {
    const RunResult* base = nullptr;
    for (const RunResult& r : results)
        if (r.technique == "none") base = &r;
    bool gpu = h.timerVerdict().checked && h.timerVerdict().trusted;
    // Announced before the table: the verdict printed at the start no longer holds.
    if (h.timerVerdict().revoked) {
        os << "\n";
        printTimerVerdict(os, h.timerVerdict());
    }
    os << "\n"
       << pad("technique", 12) << pad("wall median", 13) << pad("p5", 9) << pad("p95", 9) << pad("MAD", 8)
       << pad("cpu submit", 12) << (gpu ? pad("gpu", 10) : "") << pad("n", 5) << pad("vs none", 9)
       << "properties\n";
    for (const RunResult& r : results) {
        os << pad(r.technique, 12) << pad(fmt("%.2f ms", r.wall.median), 13) << pad(fmt("%.2f", r.wall.p5), 9)
           << pad(fmt("%.2f", r.wall.p95), 9) << pad(fmt("%.2f", r.wall.mad), 8)
           << pad(fmt("%.2f ms", r.cpuSubmit.median), 12)
           << (gpu ? pad(r.gpuTotal.n ? fmt("%.2f ms", r.gpuTotal.median) : "n/a", 10) : "")
           << pad(std::to_string(r.wall.n), 5)
           << pad(base && base->wall.median > 0 ? fmt("%.2fx", r.wall.median / base->wall.median) : "-", 9)
           << (r.properties.empty() ? "-" : r.properties) << "\n";
    }
}

void ConsoleReport::printPairedRatios(std::ostream& os, const std::vector<RunResult>& results, int rounds) {
    const size_t perRound = results.size() / size_t(rounds);
    if (perRound == 0) return;
    os << "\npaired over " << rounds << " rounds (ratio to " << results[0].technique
       << " within each round: median [min, max])\n";
    for (size_t i = 0; i < perRound; ++i) {
        std::vector<double> wall, ratio;
        for (size_t k = 0; k < size_t(rounds); ++k) {
            const RunResult& r = results[k * perRound + i];
            const RunResult& base = results[k * perRound];
            wall.push_back(r.wall.median);
            if (base.wall.median > 0) ratio.push_back(r.wall.median / base.wall.median);
        }
        const Statistics w = Statistics::compute(wall), q = Statistics::compute(ratio);
        os << pad(results[i].technique, 12) << pad(fmt("%.2f ms", w.median), 13)
           << pad(fmt("%.3fx", q.median), 9)
           << pad("[" + fmt("%.3f", q.min) + ", " + fmt("%.3f", q.max) + "]", 18)
           << (results[i].properties.empty() ? "-" : results[i].properties) << "\n";
    }
}

void ConsoleReport::printAccuracyTable(std::ostream& os,
                                       const std::vector<std::pair<RunResult, AccuracyResult>>& results) {
    os << "\n"
       << pad("technique", 12) << pad("wall median", 13) << pad("wrong %", 9) << pad("no edge %", 11)
       << pad("RMSE", 8) << pad("NaN/Inf/OOR", 13) << pad("gain cam", 10) << pad("gain light", 12)
       << pad("flicker", 9) << "properties\n";
    for (const auto& [r, a] : results) {
        std::string bad = std::to_string(a.sanity.nan) + "/" + std::to_string(a.sanity.inf) + "/" +
                          std::to_string(a.sanity.outOfRange);
        auto opt = [&](double v) { return a.stabilityMeasured ? fmt("%.2f", v) : std::string("-"); };
        os << pad(r.technique, 12) << pad(fmt("%.2f ms", r.wall.median), 13)
           << pad(fmt("%.3f", a.hard.wrongPct), 9) << pad(fmt("%.3f", a.hard.wrongNoEdgePct), 11)
           << pad(fmt("%.4f", a.soft.rmse), 8) << pad(bad, 13) << pad(opt(a.cameraGain), 10)
           << pad(opt(a.lightGain), 12) << pad(opt(a.flicker), 9)
           << (r.properties.empty() ? "-" : r.properties) << "\n";
    }
}

void ConsoleReport::printTechniqueList(std::ostream& os) {
    for (const auto& entry : TechniqueRegistry::entries()) {
        auto t = entry.create();
        const TechniqueInfo& info = t->info();
        os << info.name << "  " << info.description << "\n";
        os << "  effects:  " << effectsText(info.effects) << "\n";
        os << "  passes:   " << join(info.passes, ", ") << "\n";
        if (!info.quality.empty())
            os << "  sweep:    " << join(info.quality, "; ", [](const QualityKnob& k) {
                return k.property + " " + join(k.values, "/");
            }) << "  (bench accuracy --sweep)\n";
        if (info.properties.empty()) os << "  properties: none\n";
        for (const PropertyDesc& p : info.properties)
            os << "  " << pad(p.name, 18) << pad(propertyTypeName(p.type), 7)
               << pad("default " + p.defaultValue, 16) << pad(p.rangeText(), 16) << p.description << "\n";
        os << "\n";
    }
    os << "scenes: ";
    os << join(SceneLoader::listBuiltinScenes(), ", ") << "\n";
}

} // namespace sb
