#include "bench/floors/FloorsCommand.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <unistd.h>
#include <vector>

#include "bench/floors/FloorPass.h"
#include "bench/floors/PassProbe.h"
#include "bench/lib/callgrind/CallgrindDump.h"
#include "bench/lib/harness/Harness.h"
#include "bench/lib/options/RunOptions.h"
#include "bench/lib/output/RowExport.h"
#include "bench/lib/output/TextColumns.h"
#include "bench/lib/select/AutoResolver.h"
#include "bench/lib/statistics/Statistics.h"
#include "core/Error.h"
#include "gl/PipelineStatistics.h"
#include "registry/TechniqueRegistry.h"

namespace sb {

namespace {

namespace fs = std::filesystem;

constexpr const char* kHelp =
    R"(bench floors [options]: the options of a run (technique, scene, size, camera, submission, light,
--frames, --warmup). For each technique (GL) and each pass of its frame: the pass's kind (depth, stencil,
lit, texture, filtered), its target (size and formats), its fragments (fragment-shader invocations, as
`bench explain` counts them), and its floor: the least a pass of that kind must do for an output of the
same formats and size with as many fragments (screen-aligned rectangles, a constant colour or depth
only, one texel read per fragment for a filtered pass, stencil only for a stencil pass). The frames
alternate the technique's frame, cut with glFinish at its pass boundaries, and the floors of its passes;
each row gives the medians of the pass's and the floor's wall time and the median of their per-frame
ratios. Run under callgrind (--instr-atstart=no, without --callgrind-out-file: the dumps go to the
working folder as callgrind.out.<pid>.N), each pass and floor is also counted exactly: one dump per pass
and per floor, read back at the end, instructions per frame and their ratio.

Examples:
  bench floors -t shadowmap -t volume --size 256x256 --frames 10      each pass of two techniques against its floor
  bench floors -t vsm -t projective --scene sphere_plane --format md   a filtered and a texture pass, as Markdown
  LP_NUM_THREADS=0 valgrind --tool=callgrind --instr-atstart=no bench floors -t shadowmap --size 128x128 --frames 2 --warmup 1
                                                                       exact instructions of each pass and floor)";

/// One pass of one technique: what the census and the inspecting frame said, its floor, and the
/// measured frames.
struct PassRow {
    std::string pass;
    PassKind kind = PassKind::Lit;
    PassTarget target;
    uint64_t fragments = 0;
    uint64_t floorFragments = 0; ///< the floor's own fragment-shader invocations, as the driver counts them
    std::unique_ptr<FloorPass> floor;
    std::string note;                     ///< why there is no floor, or what to know about the row
    std::vector<double> passMs, floorMs;  ///< per measured frame (a pass entered twice: summed)
    double passIr = -1.0, floorIr = -1.0; ///< instructions per frame (under callgrind)
};

struct TechniqueRows {
    std::string name, properties;
    std::vector<PassRow> passes;
    std::string refusal; ///< the technique could not be measured: why
    int frames = 0;
};

/// Options of a run that floors would take and not honour: refused, never ignored.
void refuseUnusedOptions(const RunConfig& c) {
    auto refuse = [](const std::string& option) {
        throw Error("bench floors does not take " + option + ": it prints its rows (--format console or md)");
    };
    if (!c.csvPath.empty()) refuse("--csv");
    if (!c.samplesPath.empty()) refuse("--samples");
    if (!c.tracePath.empty()) refuse("--trace");
    if (!c.screenshotPath.empty()) refuse("--screenshot");
    if (!c.visibilityPath.empty()) refuse("--visibility");
    if (c.repeat != 1) refuse("--repeat (its frames already alternate pass and floor)");
    if (c.seconds > 0.0) refuse("--seconds (give --frames)");
    if (c.format != RowFormat::Console && c.format != RowFormat::Markdown)
        refuse("--format " + std::string(rowFormats().name(c.format)));
}

/// One frame of `technique` with `probe` on its pass boundaries.
void probedFrame(Harness& harness, Technique& technique, PassProbe& probe) {
    harness.passTimer().setObserver(&probe);
    probe.frameBegins();
    try {
        harness.renderFrame(technique);
    } catch (...) {
        harness.passTimer().setObserver(nullptr);
        throw;
    }
    harness.passTimer().setObserver(nullptr);
}

/// The floor's fragment-shader invocations as the driver counts them (a pipeline-statistics query
/// around one untimed draw): llvmpipe counts 4x4 blocks, and one more block per row of blocks where a
/// draw reaches the target's right edge (bench/floors/FloorPass.h), so the floor's count may exceed the
/// pass's by that much while its pixels are exactly the pass's count.
uint64_t countFloor(FloorPass& floor, uint64_t fragments) {
    PipelineStatistics statistics;
    statistics.begin();
    floor.draw(fragments);
    return statistics.end().fragmentShaderInvocations;
}

/// The rows of `technique`'s passes: fragments from the census `loads`, target and kind from an
/// inspecting frame, and each pass's floor (or why it has none).
std::vector<PassRow> describePasses(Harness& harness, Technique& technique, const FrameLoads& loads) {
    PassProbe inspect(true);
    probedFrame(harness, technique, inspect);
    std::vector<PassRow> rows;
    for (const auto& [pass, work] : loads.passes) {
        if (pass == "frame") continue; // the harness's own work before the first pass
        PassRow row;
        row.pass = pass;
        for (const ProbedPass& p : inspect.passes())
            if (p.name == pass) {
                row.target = p.target;
                break;
            }
        row.kind = row.target.kindOf(pass, harness.targets().fbo());
        if (!work.pipeline)
            row.note = "this context counts no fragments (no pipeline statistics): no floor";
        else if ((row.fragments = work.pipeline->fragmentShaderInvocations) == 0)
            row.note = "the driver shaded no fragment in this pass: no floor";
        else {
            try {
                row.floor = std::make_unique<FloorPass>(row.target, row.kind);
                row.floorFragments = countFloor(*row.floor, row.fragments);
            } catch (const Error& e) {
                row.note = e.what();
            }
        }
        rows.push_back(std::move(row));
    }
    return rows;
}

/// The measured frame of the technique, each pass's time summed over its intervals.
void techniqueFrame(Harness& harness, Technique& technique, PassProbe& probe, std::vector<PassRow>& rows,
                    bool measured) {
    probedFrame(harness, technique, probe);
    if (!measured) return;
    for (PassRow& row : rows) {
        double ms = 0.0;
        for (const ProbedPass& p : probe.passes())
            if (p.name == row.pass) ms += p.ms;
        row.passMs.push_back(ms);
    }
}

/// The floors of every pass that has one, each alone between two glFinish calls.
void floorsFrame(std::vector<PassRow>& rows, const std::string& dumpPrefix, bool measured) {
    for (PassRow& row : rows) {
        if (!row.floor) continue;
        finishAndDump(dumpPrefix.empty() ? "" : dumpPrefix + "skip");
        const auto t0 = std::chrono::steady_clock::now();
        row.floor->draw(row.fragments);
        finishAndDump(dumpPrefix.empty() ? "" : dumpPrefix + row.pass + ":floor");
        if (measured)
            row.floorMs.push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
}

/// Warm-up, then the measured frames: technique and floors alternate, and so does their order.
void measure(Harness& harness, Technique& technique, std::vector<PassRow>& rows,
             const std::string& dumpPrefix) {
    const RunConfig& config = harness.config();
    PassProbe probe(false);
    for (int i = 0; i < config.warmup; ++i) {
        techniqueFrame(harness, technique, probe, rows, false);
        floorsFrame(rows, "", false);
    }
    probe.setDumpPrefix(dumpPrefix);
    callgrindInstrumentation(true);
    for (int f = 0; f < config.frames; ++f) {
        if (f % 2 == 0) techniqueFrame(harness, technique, probe, rows, true);
        floorsFrame(rows, dumpPrefix, true);
        if (f % 2 == 1) techniqueFrame(harness, technique, probe, rows, true);
    }
    callgrindInstrumentation(false);
}

TechniqueRows runTechnique(Harness& harness, const TechniqueSpec& spec, size_t index, bool counting) {
    std::unique_ptr<Technique> technique = TechniqueRegistry::create(spec, Api::GL); // a typo: exit 2
    TechniqueRows out;
    out.name = technique->name();
    out.properties = technique->properties().toString();
    harness.prepare(*technique);
    // The census counts as `bench explain` does (its frame writes the visibility target, which changes no
    // count); the inspecting and measured frames render what an application would, as Harness::measure's
    // do: no visibility target, so a lit pass's target and its floor's are colour and depth-stencil.
    const FrameLoads loads = harness.measureLoads(*technique);
    harness.targets().setVisibilityOutput(false);
    struct VisibilityBackOn { // also when a frame throws: the next technique's census gets it
        Harness& harness;
        ~VisibilityBackOn() { harness.targets().setVisibilityOutput(true); }
    } visibilityBackOn{harness};
    out.passes = describePasses(harness, *technique, loads);
    measure(harness, *technique, out.passes, counting ? "floors:" + std::to_string(index) + ":" : "");
    for (PassRow& row : out.passes) row.floor.reset(); // its targets go now, not after every technique
    out.frames = harness.config().frames;
    return out;
}

// ---- instructions (under callgrind) -------------------------------------------------------------

/// Where callgrind writes this process's dumps: its default name, callgrind.out.<pid>.<n>, in the working
/// folder. Valgrind shows the client its own command line only (/proc/self/cmdline is the bench's), so
/// a --callgrind-out-file given to valgrind cannot be found from here: the help says to leave it out.
fs::path callgrindOutFile() {
    return fs::path("callgrind.out." + std::to_string(::getpid()));
}

/// Reads the dumps of this process and puts each pass's and floor's instructions per frame into the rows.
void readInstructions(std::vector<TechniqueRows>& techniques) {
    const fs::path out = callgrindOutFile();
    const fs::path dir = out.has_parent_path() ? out.parent_path() : fs::path(".");
    const std::string prefix = out.filename().string() + ".";
    std::map<std::string, double> ir;
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.path().filename().string().rfind(prefix, 0) != 0) continue;
        const CallgrindDump dump = CallgrindDump::read(entry.path().string());
        if (dump.dumpName.rfind("floors:", 0) == 0) ir[dump.dumpName] += double(dump.totalIr);
    }
    if (ir.empty())
        throw Error("bench floors: no callgrind dump named floors:* at " + out.string() +
                        ".N in the working folder: run valgrind without --callgrind-out-file (or a bench "
                        "built without valgrind's header)",
                    ExitCode::Failure);
    for (size_t t = 0; t < techniques.size(); ++t)
        for (PassRow& row : techniques[t].passes) {
            const std::string key = "floors:" + std::to_string(t) + ":" + row.pass;
            const double frames = std::max(1, techniques[t].frames);
            if (ir.count(key)) row.passIr = ir[key] / frames;
            if (ir.count(key + ":floor")) row.floorIr = ir[key + ":floor"] / frames;
        }
}

// ---- the table ------------------------------------------------------------------------------------

std::string cell(const char* format, double v, bool known) {
    return known ? formatNumber(format, v) : "-";
}

std::vector<std::string> rowCells(const std::string& technique, const PassRow& r) {
    const bool timed = !r.passMs.empty() && r.floorMs.size() == r.passMs.size();
    std::vector<double> ratios;
    if (timed)
        for (size_t i = 0; i < r.passMs.size(); ++i)
            if (r.floorMs[i] > 0.0) ratios.push_back(r.passMs[i] / r.floorMs[i]);
    const bool counted = r.passIr >= 0.0 && r.floorIr > 0.0;
    return {technique,
            r.pass,
            passKindName(r.kind),
            r.target.unusable.empty() ? r.target.text() : "-",
            std::to_string(r.fragments),
            r.floorFragments ? std::to_string(r.floorFragments) : "-",
            cell("%.3f", r.passMs.empty() ? 0.0 : Statistics::compute(r.passMs).median, !r.passMs.empty()),
            cell("%.3f", r.floorMs.empty() ? 0.0 : Statistics::compute(r.floorMs).median, !r.floorMs.empty()),
            cell("%.2f", ratios.empty() ? 0.0 : Statistics::compute(ratios).median, !ratios.empty()),
            cell("%.0f", r.passIr, r.passIr >= 0.0),
            cell("%.0f", r.floorIr, r.floorIr >= 0.0),
            cell("%.3f", counted ? r.passIr / r.floorIr : 0.0, counted),
            r.note.empty() ? "-" : r.note};
}

const std::vector<std::string> kHeadings = {
    "technique",       "pass",          "kind",     "target",     "fragments",
    "floor fragments", "pass ms",       "floor ms", "pass/floor", "pass Ir",
    "floor Ir",        "Ir pass/floor", "note"};

void print(std::ostream& os, const std::vector<TechniqueRows>& techniques, bool markdown) {
    std::vector<std::vector<std::string>> rows;
    for (const TechniqueRows& t : techniques) {
        if (!t.refusal.empty()) {
            std::vector<std::string> r(kHeadings.size(), "-");
            r[0] = t.name;
            r.back() = "refused: " + t.refusal;
            rows.push_back(r);
        }
        for (const PassRow& p : t.passes) rows.push_back(rowCells(t.name, p));
    }
    if (!markdown) {
        TextColumns table;
        table.addRow(kHeadings);
        for (auto& r : rows) table.addRow(r);
        table.print(os);
    } else {
        auto line = [&](const std::vector<std::string>& cells) {
            os << "|";
            for (const std::string& c : cells) os << " " << c << " |";
            os << "\n";
        };
        line(kHeadings);
        line(std::vector<std::string>(kHeadings.size(), "---"));
        for (auto& r : rows) line(r);
    }
    for (const TechniqueRows& t : techniques)
        if (!t.properties.empty() && t.properties != "-")
            os << (markdown ? "\n- " : "") << t.name << " " << t.properties << "\n";
}

void printHeader(std::ostream& os, Harness& harness) {
    const RunConfig& c = harness.config();
    double load[3] = {0, 0, 0};
    const bool haveLoad = ::getloadavg(load, 3) == 3;
    os << "scene " << harness.scene().name << ", " << c.width << "x" << c.height << ", camera " << c.camera
       << ", " << submitModeName(c.submit) << " submission; " << harness.rowSource().renderer << "; "
       << c.frames << " frames after " << c.warmup << " warm-up";
    if (haveLoad)
        os << "; load " << formatNumber("%.2f", load[0]) << " " << formatNumber("%.2f", load[1]) << " "
           << formatNumber("%.2f", load[2]);
    os << (callgrindRunning() ? "; under callgrind: instructions exact, times not meaningful" : "") << "\n"
       << "times: wall, each pass and each floor alone between two glFinish calls; pass/floor: median of the "
          "per-frame ratios\n\n";
}

} // namespace

int FloorsCommand::main(int argc, char** argv) {
    RunConfig config;
    bool listOnly = false;
    if (int code = RunOptions::parse(argc, argv, config, listOnly, kHelp); code >= 0) return code;
    RunOptions::requireGl(config, "bench floors");
    refuseUnusedOptions(config);
    for (const TechniqueSpec& spec : config.techniques) {
        if (spec.name == AutoResolver::kName)
            throw Error(
                "bench floors does not take -t auto: run `bench -t auto`, then give the technique it chose");
        (void)TechniqueRegistry::create(spec, Api::GL); // a typo fails before any frame (exit 2)
    }
    Harness harness(config);
    const bool counting = callgrindRunning();
    std::vector<TechniqueRows> techniques;
    ExitCode worst = ExitCode::Ok;
    for (size_t i = 0; i < config.techniques.size(); ++i) {
        try {
            techniques.push_back(runTechnique(harness, config.techniques[i], i, counting));
        } catch (const Error& error) {
            if (error.code() == ExitCode::BadInput) throw;
            TechniqueRows refused;
            refused.name = config.techniques[i].name;
            refused.refusal =
                std::string(error.what()) + " (exit code " + std::to_string(int(error.code())) + ")";
            techniques.push_back(std::move(refused));
            worst = worseExitCode(worst, error.code());
        }
    }
    if (counting) readInstructions(techniques);
    const bool markdown = config.format == RowFormat::Markdown;
    printHeader(std::cout, harness);
    print(std::cout, techniques, markdown);
    return int(worst);
}

} // namespace sb
