#include "bench/BenchApp.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <unistd.h>

#include "bench/bisect/BisectCommand.h"
#include "bench/bottleneck/BottleneckCommand.h"
#include "bench/ci/CiCommand.h"
#include "bench/compare/CompareCommand.h"
#include "bench/explain/ExplainCommand.h"
#include "bench/export/ExportCommand.h"
#include "bench/figures/FiguresCommand.h"
#include "bench/floors/FloorsCommand.h"
#include "bench/golden/GoldenCommand.h"
#include "bench/lib/harness/MeasuredHarness.h"
#include "bench/lib/options/BashCompletion.h"
#include "bench/lib/options/CliCatalog.h"
#include "bench/lib/output/StandardStreams.h"
#include "bench/lib/rows/BuildInfo.h"
#include "bench/lib/sweep/ChildProcess.h"
#include "bench/lib/sweep/SweepWorker.h"
#include "bench/merge/MergeCommand.h"
#include "bench/report/ReportCommand.h"
#include "bench/run/RunCommand.h"
#include "bench/sweep/SweepCommand.h"
#include "core/DriverTable.h"
#include "core/Error.h"
#include "core/Injection.h"
#include "core/Paths.h"
#include "core/Suggestion.h"

namespace sb {

namespace {

/// One mode of `bench`. `name` is argv[1] ("" for the plain run); a mode without a summary is not
/// listed (the sweep's worker, started by `bench sweep` only).
struct Mode {
    const char* name;
    const char* usage;   ///< as --help shows it
    const char* summary; ///< --help's description; '\n' continues it on the next line
    int (*main)(int argc, char** argv);
    /// Whether it renders, and so takes `--driver`; the others refuse the option as unknown (exit 2).
    bool renders = true;
};

int measureMain(int argc, char** argv) {
    return RunCommand::main(argc, argv, RunConfig::Mode::Measure, BenchApp::helpFooter());
}

int accuracyMain(int argc, char** argv) {
    return RunCommand::main(argc, argv, RunConfig::Mode::Accuracy, BenchApp::helpFooter());
}

int workerMain(int argc, char** argv) {
    if (argc != 2) throw Error("usage: bench sweep-worker JOB.json (started by bench sweep, not by hand)");
    return SweepWorker::run(argv[1]);
}

// The one table of modes. Order is the order of --help.
constexpr Mode kModes[] = {
    {"", "bench [options]", "measure frame times (the default)", measureMain},
    {"accuracy", "bench accuracy [options]",
     "measure, then judge each technique's visibility against the exact\n"
     "Embree reference at the same pixels (errors, NaN count, stability);\n"
     "--sweep walks every quality knob (accuracy against time)",
     accuracyMain},
    {"sweep", "bench sweep [FILE.json] [axes]",
     "every combination of techniques, scenes, instances, scale, submit,\n"
     "camera, size, light; --resume, --shard i/N (bench sweep --help)",
     SweepCommand::main},
    {"bottleneck", "bench bottleneck [axes]",
     "is each technique CPU-, vertex- or fill-limited here? (thesis 6.2)", BottleneckCommand::main},
    {"figures", "bench figures", "rerun and replot the reproduced figures of results/figures/",
     FiguresCommand::main},
    {"golden", "bench golden --check|--update",
     "every technique x submission mode x built-in scene against the\n"
     "committed goldens and accuracy bounds, or rewrite them (results/goldens/)",
     GoldenCommand::main},
    {"ci", "bench ci [--quick|--update]",
     "the perf gate: exact work, instructions per frame, wall time against\n"
     "the committed baseline or another build/driver (results/ci/)",
     CiCommand::main},
    {"explain", "bench explain [options]",
     "what the scene asks for, what each technique delivers of it, the\n"
     "permutation it compiles and the passes one frame runs or skips",
     ExplainCommand::main},
    {"floors", "bench floors [options]",
     "each pass of each technique against its floor: the least a pass of\n"
     "its kind does for the same output and fragments (times, instructions)",
     FloorsCommand::main},
    {"bisect", "bench bisect GOOD BAD -c CONFIG",
     "the first commit of GOOD..BAD where a configuration's exact work,\n"
     "instructions per frame or image changed (builds in a worktree)",
     BisectCommand::main},
    {"compare", "bench compare BASE NEW", "the perf gate's verdict on two result CSVs", CompareCommand::main,
     false},
    {"merge", "bench merge -o OUT IN...", "join the CSVs of a sharded sweep", MergeCommand::main, false},
    {"export", "bench export IN.csv --format md",
     "a result CSV as a Markdown table, JSON, CSV, Google Benchmark JSON\n"
     "or github-action-benchmark input (dashboards)",
     ExportCommand::main, false},
    {"report", "bench report DIR [-o PAGE]", "results as one HTML page (sortable)", ReportCommand::main,
     false},
    {"sweep-worker", "bench sweep-worker JOB.json", nullptr, workerMain, false},
};

/// Column where the modes' summaries start in --help.
constexpr size_t kSummaryColumn = 35;

constexpr const char* kExamples = R"(Examples:
  bench                                            shadowmap, aircraft x200, 1024x1024 (the default run)
  bench -t none -t shadowmap --instances 200       baseline and technique side by side
  bench -t shadowmap:resolution=4096:pcf=3         properties inline (see --list for every knob)
  bench --submit immediate --frames 20             the CPU-bound submission path of the thesis
  bench -t shadowmap --back-faces draw             every face drawn (the default culls closed meshes' backs)
  bench --scene teapot --camera near --scale 10    fill-bound variant
  bench --csv results.csv --samples frames.csv     append a row per technique, keep per-frame samples
  bench --screenshot out.png --visibility vis.png  images of the last frame
  bench --model path/to/model.obj                  your own caster through assimp
  bench --window                                   on-screen viewer (GLFW): overlay, Tab switches, V visibility
  bench accuracy -t shadowmap --sweep --csv acc.csv  error against time for every shadowmap knob
  bench -t none -t shadowmap --repeat 5            interleaved rounds: ratios from runs side by side
  bench -t none -t shadowmap --format json         the rows as JSON on stdout (also csv, md)
  bench --api vulkan -t shadowmap -t volume        the same on Vulkan (lavapipe; --list: techniques, devices)
  bench -t none -t shadowmap --trace run.json     frames and passes as a timeline (ui.perfetto.dev)
  bench sweep -t none -t shadowmap -n 1,50,100,200 --csv inst.csv
  bench bottleneck -t none -t shadowmap -n 100 --csv bn.csv
  bench explain -t planar --scene aircraft         effects asked for and delivered, passes run
  bench floors -t shadowmap -t volume              each pass against the least a pass of its kind does
  bench report out/                                the CSVs, figures and images of out/ as one HTML page
  bench export r.csv --format gbench -o r.json     Google Benchmark JSON for dashboards
  bench --version                                  version, the commit it was built from, build type)";

constexpr const char* kExitCodes =
    R"(Exit codes: 0 ok, 1 run failed (GL error, I/O), 2 the input is wrong (option, value, file, index),
3 this machine or context lacks what is needed (an extension, a device, a loader).
With several techniques, one that fails or refuses gets a row (status, error) and the rest still run;
the exit code is then the worst: 1 over 2 over 3 (nothing measured: the worst error, no row).)";

} // namespace

std::string BenchApp::helpFooter() {
    std::string out = "Modes:\n";
    for (const Mode& m : kModes) {
        if (!m.summary) continue;
        std::string line = std::string("  ") + m.usage;
        line.resize(std::max(kSummaryColumn, line.size() + 1), ' ');
        for (const char* c = m.summary; *c; ++c)
            line += *c == '\n' ? "\n" + std::string(kSummaryColumn, ' ') : std::string(1, *c);
        out += line + "\n";
    }
    return out + "\n" + kExamples + "\n\n" + kExitCodes;
}

std::string BenchApp::versionText() {
    std::string data;
    try {
        data = std::filesystem::path(Paths::findResourceDirectory("shaders")).parent_path().string();
    } catch (const Error& e) {
        data = std::string("none found (") + e.what() + ")";
    }
    return std::string("shadowbench ") + BuildInfo::version() + "\ncommit " + BuildInfo::commit() +
           "\nbuild " + BuildInfo::buildType() + ", " + BuildInfo::compiler() + "\ndata " + data + "\n";
}

std::vector<CliCommand> BenchApp::catalog() {
    std::vector<CliCommand> out;
    for (const Mode& m : kModes) {
        if (!m.summary) continue;
        // The entry point sees a bare argv; under the capture it returns once its CLI::App is built.
        std::string program = *m.name ? m.name : "bench";
        char* argv[] = {program.data(), nullptr};
        out.push_back(CliCatalog::describe([&] { return m.main(1, argv); }, m.name, m.usage, m.summary));
    }
    return out;
}

ManPage::Text BenchApp::manPageText() {
    return {std::string("shadowbench ") + BuildInfo::version(), kExamples, kExitCodes};
}

namespace {

/// The hidden generators (cmake/ManAndCompletion.cmake runs them at build time): `bench --man` and
/// `bench --completion bash`. Returns -1 when `argv` asks for neither.
int generate(int argc, char** argv) {
    const std::string what = argv[1];
    if (what == "--man") {
        if (argc > 2) throw Error("--man takes no other arguments");
        std::cout << ManPage::render(BenchApp::catalog(), BenchApp::manPageText());
        return 0;
    }
    if (what == "--completion") {
        if (argc != 3 || std::string(argv[2]) != "bash") throw Error("usage: bench --completion bash");
        std::cout << BashCompletion::render(BenchApp::catalog());
        return 0;
    }
    return -1;
}

/// A bare first word is always meant as a subcommand: the plain run takes no positional argument.
[[noreturn]] void unknownSubcommand(const std::string& word) {
    std::vector<std::string> names;
    for (const Mode& m : kModes)
        if (*m.name && m.summary) names.emplace_back(m.name);
    throw Error("unknown subcommand " + word + Suggestion::didYouMean(word, names) + " (see bench --help)");
}

/// The dynamic loader refuses a driver's library that is missing or broken before main() runs, with
/// exit code 127 and its own line; tried first in a child (`bench --version`, milliseconds) so that the
/// refusal is this program's one line, exit 3, naming the driver.
void requireStartable(const std::string& self, const std::string& driver) {
    const ChildExit probe = ChildProcess::run({self, "--version"}, {}, [](const std::string&) {});
    if (probe.ok()) return;
    std::string last = probe.stderrTail;
    while (!last.empty() && last.back() == '\n') last.pop_back();
    last = last.substr(last.rfind('\n') == std::string::npos ? 0 : last.rfind('\n') + 1);
    throw Error("--driver " + driver + ": this program cannot start on its libraries (" + probe.describe() +
                    "): " + last,
                ExitCode::Unsupported);
}

/// `--driver NAME|PATH` (core/DriverTable.h): the libraries are chosen when a process starts, so a run
/// asked for another driver than the one it runs on runs itself again with that driver's environment.
/// The option stays in argv for the subcommand, which records it. Returns only when the process runs
/// on the driver asked for (or none was asked for).
void runOnRequestedDriver(char** argv, int argc) {
    constexpr const char* kRerun = "SHADOWBENCH_DRIVER_RERUN"; // guards against running again forever
    const std::string wanted = DriverTable::requested(argc, argv);
    const bool rerun = std::getenv(kRerun) != nullptr;
    ::unsetenv(kRerun);
    if (wanted.empty()) return;
    const Driver driver = DriverTable::resolve(wanted);
    if (DriverTable::isActive(driver)) return;
    if (rerun)
        throw Error("--driver " + wanted + ": its environment did not take effect in the new process",
                    ExitCode::Failure);
    DriverTable::activate(driver);
    const std::string self = ChildProcess::selfExecutable();
    requireStartable(self, wanted);
    ::setenv(kRerun, "1", 1);
    ::execv(self.c_str(), argv);
    throw Error("--driver " + wanted + ": cannot run " + self + " again: " + std::strerror(errno),
                ExitCode::Failure);
}

/// The mode `word` names (argv[1]), or nullptr for the plain run and words that are no mode.
const Mode* modeNamed(const std::string& word) {
    for (const Mode& m : kModes)
        if (*m.name && word == m.name) return &m;
    return nullptr;
}

/// `bench --driver X SUB ...` is `bench SUB --driver X ...`: the driver reads as a choice made for the
/// whole program, so it may come before the subcommand. Moves it behind the subcommand's word in place,
/// so that the subcommand parses (and records, or refuses) it like its other options.
void driverAfterSubcommand(int argc, char** argv) {
    if (argc < 3) return;
    const std::string first = argv[1];
    const int width = first == "--driver" ? 2 : first.rfind("--driver=", 0) == 0 ? 1 : 0;
    if (width == 0 || argc <= width + 1 || !modeNamed(argv[width + 1])) return;
    std::rotate(argv + 1, argv + 1 + width, argv + 2 + width);
}

} // namespace

int BenchApp::dispatch(int argc, char** argv) {
    const std::string sub = argc > 1 ? argv[1] : "";
    if (sub == "--version" || sub == "-V") {
        if (argc > 2) throw Error("--version takes no other arguments", ExitCode::BadInput);
        std::cout << versionText();
        return 0;
    }
    if (argc > 1)
        if (int code = generate(argc, argv); code >= 0) return code;
    for (const Mode& m : kModes)
        if (*m.name && sub == m.name) return m.main(argc - 1, argv + 1);
    if (!sub.empty() && sub[0] != '-') unknownSubcommand(sub);
    return measureMain(argc, argv);
}

int BenchApp::main(int argc, char** argv) {
    StandardStreams::protect(); // before any file is opened (see bench/lib/output/StandardStreams.h)
    MeasuredHarness::pinAllocator();
    try {
        checkInjections(); // a typo in SHADOWBENCH_INJECT must not measure the unmodified code
        driverAfterSubcommand(argc, argv);
        // Only a mode that renders acts on --driver; the others refuse it as an option they lack.
        const Mode* mode = argc > 1 ? modeNamed(argv[1]) : nullptr;
        if (!mode || mode->renders) runOnRequestedDriver(argv, argc);
        return dispatch(argc, argv);
    } catch (const Error& e) {
        std::cerr << "bench: error: " << e.what() << "\n";
        return int(e.code());
    } catch (const std::exception& e) {
        std::cerr << "bench: error: " << e.what() << "\n";
        return int(ExitCode::Failure);
    }
}

} // namespace sb
