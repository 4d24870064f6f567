#include "bench/run/ConsoleReport.h"

#include "bench/lib/output/TextColumns.h"
#include "core/Strings.h"

#include <ostream>
#include <string>

#include "core/Error.h"
#include "gl/backends/BackendRegistry.h"
#include "registry/TechniqueRegistry.h"
#include "scenes/SceneLoader.h"
#include "vk/VulkanContext.h"

namespace sb {

namespace {
std::string fmt(const char* f, double v) {
    return formatNumber(f, v);
}

std::string propertiesText(const RunResult& r) {
    return r.properties.empty() ? "-" : r.properties;
}

/// Techniques per round: `results` holds `rounds` rounds of the same techniques (one round when the
/// count does not divide, which RunCommand never produces).
size_t roundSize(const std::vector<RunResult>& results, int rounds) {
    if (rounds < 1 || results.size() % size_t(rounds) != 0) return results.size();
    return results.size() / size_t(rounds);
}

std::string effectsText(EffectMask m) {
    return m ? effectMaskToString(m) : "(no shadows)";
}
} // namespace

void ConsoleReport::printHeader(std::ostream& os, const MeasuredHarness& h) {
    printHeader(os, h.rowSource());
}

void ConsoleReport::printHeader(std::ostream& os, const RowSource& h) {
    const RunConfig& cfg = h.config;
    const size_t layout = h.scene.countLayoutInstances();
    const bool vulkan = h.api == "vulkan";
    os << "backend   " << h.backend << (h.device.empty() || vulkan ? "" : " (" + h.device + ")") << "\n"
       << (vulkan ? "device    " : "renderer  ") << h.renderer << "\n"
       << (vulkan ? "Vulkan    " + h.apiVersion + ", " + h.vendor : "GL        " + h.glVersion) << "\n"
       << "scene     " << h.scene.name << ": " << layout << " instances, scale " << cfg.sceneOptions.scale
       << ", " << h.scene.totalTriangles() << " triangles, camera " << cfg.camera << ", " << cfg.width << "x"
       << cfg.height << ", submit " << submitModeName(cfg.submit) << "\n"
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

void ConsoleReport::printTable(std::ostream& os, const MeasuredHarness& h,
                               const std::vector<RunResult>& results, int rounds) {
    printTable(os, h.timerVerdict(), results, rounds);
}

void ConsoleReport::printTable(std::ostream& os, const TimerVerdict& verdict,
                               const std::vector<RunResult>& results, int rounds) {
    if (results.empty()) return;
    const size_t perRound = roundSize(results, rounds);
    const bool gpu = verdict.checked && verdict.trusted;
    // Announced before the table: the verdict printed at the start no longer holds.
    if (verdict.revoked) {
        os << "\n";
        printTimerVerdict(os, verdict);
    }
    const bool several = results.size() > perRound;
    TextColumns table;
    std::vector<std::string> head{"technique"};
    if (several) head.push_back("round");
    head.insert(head.end(), {"wall median", "p5", "p95", "MAD", "cpu submit"});
    if (gpu) head.push_back("gpu");
    head.insert(head.end(), {"n", "vs " + results[0].technique, "properties"});
    table.addRow(std::move(head));
    for (size_t i = 0; i < results.size(); ++i) {
        const RunResult& r = results[i];
        const RunResult& base = results[i - i % perRound]; // the first technique of this row's round
        std::vector<std::string> row{r.technique};
        if (several) row.push_back(std::to_string(i / perRound + 1));
        row.insert(row.end(), {fmt("%.2f ms", r.wall.median), fmt("%.2f", r.wall.p5), fmt("%.2f", r.wall.p95),
                               fmt("%.2f", r.wall.mad), fmt("%.2f ms", r.cpuSubmit.median)});
        if (gpu) row.push_back(r.gpuTotal.n ? fmt("%.2f ms", r.gpuTotal.median) : "n/a");
        row.insert(row.end(), {std::to_string(r.wall.n),
                               base.wall.median > 0 ? fmt("%.2fx", r.wall.median / base.wall.median) : "-",
                               propertiesText(r)});
        table.addRow(std::move(row));
    }
    os << "\n";
    table.print(os);
}

void ConsoleReport::printPairedRatios(std::ostream& os, const std::vector<RunResult>& results, int rounds) {
    if (results.empty() || rounds < 1) return;
    const size_t perRound = roundSize(results, rounds);
    const size_t count = results.size() / perRound;
    os << "\npaired over " << count << " rounds (ratio to " << results[0].technique
       << " within each round: median [min, max])\n";
    TextColumns table;
    table.addRow({"technique", "wall median", "vs " + results[0].technique, "[min, max]", "properties"});
    for (size_t i = 0; i < perRound; ++i) {
        std::vector<double> wall, ratio;
        for (size_t k = 0; k < count; ++k) {
            const RunResult& r = results[k * perRound + i];
            const RunResult& base = results[k * perRound];
            wall.push_back(r.wall.median);
            if (base.wall.median > 0) ratio.push_back(r.wall.median / base.wall.median);
        }
        const Statistics w = Statistics::compute(wall), q = Statistics::compute(ratio);
        table.addRow({results[i].technique, fmt("%.2f ms", w.median), fmt("%.3fx", q.median),
                      "[" + fmt("%.3f", q.min) + ", " + fmt("%.3f", q.max) + "]",
                      propertiesText(results[i])});
    }
    table.print(os);
}

void ConsoleReport::printAccuracyTable(std::ostream& os,
                                       const std::vector<std::pair<RunResult, AccuracyResult>>& results) {
    TextColumns table;
    table.addRow({"technique", "wall median", "wrong %", "no edge %", "RMSE", "NaN/Inf/OOR", "gain cam",
                  "gain light", "flicker", "properties"});
    for (const auto& [r, a] : results) {
        std::string bad = std::to_string(a.sanity.nan) + "/" + std::to_string(a.sanity.inf) + "/" +
                          std::to_string(a.sanity.outOfRange);
        // Captured by value, not the binding: lambdas capture structured bindings only from clang 16.
        auto opt = [measured = a.stabilityMeasured](double v) {
            return measured ? fmt("%.2f", v) : std::string("-");
        };
        table.addRow({r.technique, fmt("%.2f ms", r.wall.median), fmt("%.3f", a.hard.wrongPct),
                      fmt("%.3f", a.hard.wrongNoEdgePct), fmt("%.4f", a.soft.rmse), bad, opt(a.cameraGain),
                      opt(a.lightGain), opt(a.flicker), propertiesText(r)});
    }
    os << "\n";
    table.print(os);
}

namespace {

/// The APIs a technique runs on, and what the other one says when it has no form there.
std::string apisText(const TechniqueRegistry::Entry& entry) {
    if (!entry.gl) return "vulkan (no GL form: " + std::string(entry.glRefusal ? entry.glRefusal : "") + ")";
    return entry.vulkan ? "gl, vulkan" : "gl (no Vulkan form: --api vulkan exits 3)";
}

} // namespace

void ConsoleReport::printTechniqueList(std::ostream& os) {
    for (const auto& entry : TechniqueRegistry::entries()) {
        const auto t = TechniqueRegistry::describe(TechniqueSpec{entry.name, {}});
        const TechniqueInfo& info = t->info();
        os << info.name << "  " << info.description << "\n";
        os << "  effects:  " << effectsText(info.effects) << "\n";
        os << "  passes:   " << join(info.passes, ", ") << "\n";
        os << "  apis:     " << apisText(entry) << "\n";
        const std::vector<Capability> vulkanNeeds = info.capabilitiesOf(Api::Vulkan);
        if (!vulkanNeeds.empty())
            os << "  needs:    " << join(vulkanNeeds, ", ", [](const Capability& c) { return c.name; })
               << " on Vulkan\n";
        if (!info.quality.empty())
            os << "  sweep:    " << join(info.quality, "; ", [](const QualityKnob& k) {
                return k.property + " " + join(k.values, "/");
            }) << "  (bench accuracy --sweep)\n";
        if (!info.matrixVariants.empty())
            os << "  matrix:   variants " << join(info.matrixVariants, ", ", [](const MatrixVariant& v) {
                return v.properties + " (rule " + accuracyRuleName(v.rule) + ")";
            }) << ": cells of their own in bench golden, beside the default's\n";
        if (info.properties.empty()) os << "  properties: none\n";
        TextColumns properties("  ");
        for (const PropertyDesc& p : info.properties)
            properties.addRow({p.name, propertyTypeName(p.type), "default " + p.defaultValue, p.rangeText(),
                               p.description});
        properties.print(os);
        os << "\n";
    }
    os << "scenes: ";
    os << join(SceneLoader::listBuiltinScenes(), ", ") << "\n";
    printVulkanDevices(os);
}

void ConsoleReport::printVulkanDevices(std::ostream& os) {
    // --api vulkan --vk-device N picks one of these; a machine without a Vulkan driver says so here
    // and runs GL as before.
    try {
        const std::vector<VulkanDeviceInfo> devices = VulkanContext::listDevices();
        os << "vulkan devices (--api vulkan --vk-device N; default: lavapipe, else 0):\n";
        for (const VulkanDeviceInfo& d : devices)
            os << "  " << d.index << "  " << d.name << " (" << d.type << ", Vulkan " << d.apiVersion << ", "
               << d.driver << ")\n";
    } catch (const Error& e) {
        os << "vulkan devices: none (" << e.what() << ")\n";
    }
}

} // namespace sb
