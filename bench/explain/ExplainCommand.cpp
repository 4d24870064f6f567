#include "bench/explain/ExplainCommand.h"

#include <iostream>
#include <memory>
#include <sstream>

#include "bench/lib/harness/Harness.h"
#include "bench/lib/harness/VulkanHarness.h"
#include "bench/lib/options/RunOptions.h"
#include "bench/lib/output/TextColumns.h"
#include "bench/lib/select/AutoResolver.h"
#include "core/Error.h"
#include "registry/TechniqueRegistry.h"
#include "techniques/EffectCoverage.h"

namespace sb {

namespace {

std::string workText(const PassWork& w) {
    std::ostringstream os;
    os << w.submitted.drawCalls << " draws, " << w.submitted.triangles << " triangles, "
       << w.submitted.glCalls << " GL calls";
    if (w.pipeline)
        os << ", " << w.pipeline->vertexShaderInvocations << " vertices, "
           << w.pipeline->fragmentShaderInvocations << " fragments";
    return os.str();
}

void printEffects(std::ostream& os, const EffectCoverage& c) {
    TextColumns t("  ");
    t.addRow({"effects requested", effectMaskToString(c.requested)});
    t.addRow({"effects delivered", effectMaskToString(c.delivered)});
    std::string missing = effectMaskToString(c.missing);
    if (c.fallsShort())
        missing += "  (a run warns; --strict-effects refuses it)";
    else if (c.missing)
        missing += "  (a baseline: it draws no shadow by design)";
    t.addRow({"cannot deliver", missing});
    t.print(os);
}

/// What a pass did: "ran"; "no GL work" when the pipeline counted nothing and nothing was drawn (the
/// pass was entered, e.g. a blur of radius 0, or it works on the CPU only); "ran" too where the context
/// cannot count the pipeline, since full-screen passes draw outside the submitter's counts.
const char* passStatus(const std::string& pass, const PassWork& w) {
    if (pass == "frame") return "harness";
    const bool drew = w.submitted.drawCalls > 0 || w.submitted.glCalls > 0;
    const bool counted =
        w.pipeline && (w.pipeline->vertexShaderInvocations > 0 || w.pipeline->fragmentShaderInvocations > 0);
    return drew || counted || !w.pipeline ? "ran" : "no GL work";
}

/// The passes of one census frame, then the declared passes it never entered, with the technique's
/// reason where it gave one (PassTimer::skip).
void printPasses(std::ostream& os, const TechniqueInfo& info, const FrameLoads& loads) {
    os << "  passes of one frame (exact counts, not timed):\n";
    TextColumns t("    ");
    for (const auto& [pass, w] : loads.passes) t.addRow({pass, passStatus(pass, w), workText(w)});
    for (const std::string& pass : info.passes) {
        bool ran = false;
        for (const auto& entry : loads.passes) ran = ran || entry.first == pass;
        if (ran) continue;
        std::string why = "declared, not entered in this frame (see the counters)";
        for (const auto& [skipped, reason] : loads.skipped)
            if (skipped == pass) why = reason;
        t.addRow({pass, "skipped", why});
    }
    t.print(os);
}

void printCounters(std::ostream& os, const Counters& counters) {
    if (counters.empty()) return;
    os << "  counters:\n";
    TextColumns t("    ");
    for (const auto& [name, value] : counters) t.addRow({name, formatNumber("%.10g", value)});
    t.print(os);
}

constexpr const char* kHelp =
    R"(bench explain [options]: the options of a run (technique, scene, size, camera, submission,
light ...), nothing timed. For the scene and each technique it prints the effects the scene asks for,
those the technique delivers and those it cannot (a run warns about them, --strict-effects refuses
them), the shader permutation compile() chose, and the passes of one frame with their exact work:
"ran", "no GL work" (entered, nothing drawn), "skipped" (declared, never entered). A technique that
refuses the configuration is explained with its refusal, and the command exits with its code.

Examples:
  bench explain -t planar --scene aircraft                    self_shadowing is missing: why planar warns
  bench explain -t shadowmap -t volume --scene sphere_plane   what each pass draws, side by side
  bench explain -t vsm:blur=0 --submit instanced              the blur pass entered without work
  bench explain -t none -t shadowmap --scene point_light      a refusal explained (exit code 3)
  bench explain --api vulkan -t volume --scene sphere_plane   the same frame on Vulkan (pipeline statistics))";

/// A technique of the command line: its form on the run's API, or why there is none (a technique
/// without a Vulkan form is explained with that refusal, as one that refuses the configuration).
struct Explained {
    std::unique_ptr<Technique> technique;
    std::unique_ptr<Technique> described; ///< another API's form, for the header, where `technique` is null
    std::string refusal;
    ExitCode code = ExitCode::Ok;
};

std::vector<Explained> createTechniques(const RunConfig& config) {
    const Api api = config.api == RunConfig::Api::Vulkan ? Api::Vulkan : Api::GL;
    std::vector<Explained> out;
    for (const TechniqueSpec& spec : config.techniques) {
        // The choice of -t auto is a timed calibration, which explain (untimed, one frame) does not make.
        if (spec.name == AutoResolver::kName)
            throw Error("bench explain does not take -t auto: run `bench -t auto` with these options, "
                        "then explain the technique it chose");
        Explained e;
        try {
            e.technique = TechniqueRegistry::create(spec, api);
        } catch (const Error& error) {
            if (error.code() != ExitCode::Unsupported) throw; // a typo fails before any frame
            e.described = TechniqueRegistry::describe(spec);
            e.refusal = error.what();
            e.code = error.code();
        }
        out.push_back(std::move(e));
    }
    return out;
}

std::unique_ptr<MeasuredHarness> createHarness(const RunConfig& config) {
    if (config.api == RunConfig::Api::Vulkan) return std::make_unique<VulkanHarness>(config);
    return std::make_unique<Harness>(config);
}

} // namespace

int ExplainCommand::main(int argc, char** argv) {
    RunConfig config;
    bool listOnly = false;
    if (int code = RunOptions::parse(argc, argv, config, listOnly, kHelp); code >= 0) return code;
    // Declared before the techniques, so destroyed after them: they release API objects in their
    // destructors (as in RunCommand::run).
    std::unique_ptr<MeasuredHarness> harnessOwner;
    std::vector<Explained> techniques = createTechniques(config); // created first: a typo fails first
    harnessOwner = createHarness(config);
    MeasuredHarness& harness = *harnessOwner;
    const Scene& scene = harness.scene();
    std::cout << "scene " << scene.name << ": " << scene.lights.size() << " light(s), "
              << scene.totalTriangles() << " triangles; " << config.width << "x" << config.height
              << ", camera " << config.camera << ", " << submitModeName(config.submit) << " submission; "
              << harness.rowSource().renderer << (harness.api() == Api::Vulkan ? " (vulkan)" : "") << "\n";
    ExitCode worst = ExitCode::Ok;
    for (Explained& e : techniques) {
        const Technique& shown = e.technique ? *e.technique : *e.described;
        const TechniqueInfo& info = shown.info();
        std::cout << "\n" << info.name << " " << shown.properties().toString() << "\n";
        const EffectCoverage coverage = EffectCoverage::of(scene.effects, info.effects);
        printEffects(std::cout, coverage);
        try {
            if (!e.technique) throw Error(e.refusal, e.code);
            harness.prepare(*e.technique);
            const FrameLoads loads = harness.measureLoads(*e.technique);
            std::cout << "  permutation        " << e.technique->permutationKey() << "\n";
            printPasses(std::cout, info, loads);
            printCounters(std::cout, e.technique->counters());
        } catch (const Error& error) {
            std::cout << "  refused            " << error.what() << " (exit code " << int(error.code())
                      << ")\n";
            worst = worseExitCode(worst, error.code());
        }
    }
    for (const std::string& message : harness.takeValidationMessages())
        std::cerr << "bench: vulkan validation: " << message << "\n";
    if (harness.validationErrors() > 0) worst = worseExitCode(worst, ExitCode::Failure);
    return int(worst);
}

} // namespace sb
