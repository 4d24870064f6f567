#include "bench/bisect/BisectCommand.h"

#include <csignal>
#include <filesystem>
#include <iostream>

#include "bench/lib/bisect/Bisection.h"
#include "bench/lib/options/CliParse.h"
#include "bench/lib/options/DriverOption.h"
#include "bench/lib/output/AtomicFile.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/output/ProgressBar.h"
#include "bench/lib/sweep/ChildProcess.h"
#include "bench/lib/sweep/InterruptGuard.h"
#include "core/DriverTable.h"
#include "core/Error.h"
#include "core/Paths.h"

namespace sb {

namespace {

namespace fs = std::filesystem;

constexpr const char* kFooter = R"(Examples:
  bench bisect v0.9 HEAD -c shadowmap_aircraft              where shadowmap_aircraft's exact work changed
  bench bisect HEAD~40 HEAD -c volume_aircraft --signal instructions   Ir per frame beyond 0.5% (valgrind)
  bench bisect abc123 main --signal image -- -t pcss --size 64x64 --frames 1   run options after --
  bench bisect HEAD~64 HEAD -c none_aircraft --json bisect.json --jobs 2
  bench bisect --clean                                       remove the kept build folder

Each commit of `git rev-list --first-parent GOOD..BAD` the search probes is checked out into one
worktree and built (target bench) in one build folder kept for the next bisection, outside the source
tree; ccache is used when on PATH. A commit that does not build or run is skipped. Builds: GOOD and at
most ceil(log2(N + 1)) probes for N commits, without skips.
Exit codes: 0 found, 1 GOOD and BAD do not differ (or skipped commits hide the answer), 2 bad input,
3 git, cmake, ninja or valgrind missing.)";

struct BisectOptions {
    std::string driver; ///< --driver, applied by BenchApp before this command runs
    std::string good, bad, config, signal = "work", repo, suite, buildDir, json;
    int jobs = 0;
    double irThreshold = 0.005;
    bool clean = false;
    std::vector<std::string> runArgs; ///< after `--`
};

/// The repository: --repo, else the checkout holding the working directory, else the source tree this
/// bench was built from (the last of Paths' roots).
GitRepo findRepo(const std::string& given) {
    if (!given.empty()) return GitRepo(given);
    if (!GitRepo::toplevelOf(".").empty()) return GitRepo(".");
    const auto roots = Paths::searchRoots();
    if (!roots.empty() && !GitRepo::toplevelOf(roots.back()).empty()) return GitRepo(roots.back());
    throw Error("bisect: not inside a git checkout (give --repo DIR)", ExitCode::BadInput);
}

/// Pulls `--name V` / `--name=V` out of `args`; returns V or `fallback`.
int takeCount(std::vector<std::string>& args, const std::string& name, int fallback) {
    for (size_t i = 0; i < args.size(); ++i) {
        std::string value;
        size_t n = 0;
        if (args[i] == name && i + 1 < args.size())
            value = args[i + 1], n = 2;
        else if (args[i].rfind(name + "=", 0) == 0)
            value = args[i].substr(name.size() + 1), n = 1;
        if (!n) continue;
        args.erase(args.begin() + long(i), args.begin() + long(i + n));
        try {
            return std::stoi(value);
        } catch (const std::exception&) {
            throw Error(name + " " + value + ": not a count", ExitCode::BadInput);
        }
    }
    return fallback;
}

/// The suite and configuration a run uses: -c CONFIG of the suite file, or the options after `--` as
/// a configuration of its own (their --frames and --warmup become its frame counts).
std::pair<CiSuite, CiConfig> configuration(const BisectOptions& o) {
    if (!o.config.empty() && !o.runArgs.empty())
        throw Error("bisect: give -c CONFIG or run options after --, not both", ExitCode::BadInput);
    if (o.config.empty() && o.runArgs.empty())
        throw Error("bisect: say what to run: -c CONFIG (results/ci/suite.json) or run options after --",
                    ExitCode::BadInput);
    if (!o.config.empty()) {
        std::string path = o.suite.empty() ? Paths::findResource("results/ci/suite.json") : o.suite;
        if (path.empty()) throw Error("cannot find results/ci/suite.json (give --suite)", ExitCode::BadInput);
        CiSuite suite = CiSuite::load(path);
        CiConfig config = suite.config(o.config);
        // A configuration bound to other drivers cannot run here, at any commit: said before any build.
        if (!config.runsOn(DriverTable::current()))
            throw Error("bisect -c " + o.config + ": not on the driver " + DriverTable::current() + ", it " +
                            config.notRunReason() + " (bench --driver " + config.drivers.front() +
                            " bisect ...)",
                        ExitCode::Unsupported);
        return {suite, config};
    }
    CiSuite suite;
    suite.name = suite.path = "the command line";
    std::vector<std::string> args = o.runArgs;
    std::erase(args, std::string("--no-timer-check")); // every run adds it (SuiteRunner.h)
    suite.work.frames = takeCount(args, "--frames", 1);
    suite.work.warmup = takeCount(args, "--warmup", 0);
    suite.instructions.frames = suite.work.frames;
    suite.instructions.warmup = suite.work.warmup;
    return {suite, CiConfig{"command_line", "balanced", args}};
}

std::string describeValue(const SignalValue& v) {
    std::string out;
    for (const auto& [k, cell] : v) out += (out.empty() ? "" : ", ") + k + "=" + cell;
    return out;
}

/// The result on stdout: the first changed commit with its changes, or why there is none.
void printResult(const BisectResult& r, const GitRepo& repo, const BisectSignal& signal) {
    const char* what = BisectSignal::name(signal.kind());
    const auto& o = r.outcome;
    if (o.kind == BisectOutcome::Kind::Found) {
        const BisectStep& s = *r.step(r.commits[o.firstBad]);
        std::cout << "first commit where " << what << " changed: " << s.commit << " " << s.subject << "\n"
                  << "  commit " << o.firstBad + 1 << " of " << r.commits.size() << " after GOOD "
                  << r.good.substr(0, 12) << "\n";
        for (const std::string& c : s.changes) std::cout << "  " << c << "\n";
    } else if (o.kind == BisectOutcome::Kind::NotFound) {
        std::cout << "GOOD " << r.good.substr(0, 12) << " and BAD " << r.bad.substr(0, 12)
                  << " give the same " << what << " (" << describeValue(r.steps.front().value).substr(0, 300)
                  << ")\n";
    } else {
        std::cout << "undecided: only skipped commits are left; the first commit where " << what
                  << " changed is one of:\n";
        for (size_t i : o.candidates)
            std::cout << "  " << r.commits[i] << " " << repo.subject(r.commits[i]) << "\n";
        if (o.mayBeNone) std::cout << "  (or none: no probed commit differed from GOOD)\n";
    }
    size_t skipped = 0;
    for (const BisectStep& s : r.steps) skipped += s.verdict == "skipped" ? 1 : 0;
    std::cout << "builds: " << r.steps.size() << " (GOOD and " << r.steps.size() - 1 << " probes of "
              << r.commits.size() << " commits; at most "
              << BisectSearch::maxEvaluations(r.commits.size()) + 1 << " without skips), skipped: " << skipped
              << "\n";
    for (const BisectStep& s : r.steps)
        if (s.verdict == "skipped")
            std::cout << "  skipped " << s.commit.substr(0, 12) << ": " << s.reason << "\n";
    std::cout << "total time: " << ProgressBar::formatDuration(r.totalSeconds)
              << "; build folder kept: " << r.buildFolder << " (bench bisect --clean removes it)\n";
}

int cleanOnly(const BisectOptions& o) {
    const std::string folder = BisectWorkspace::folderFor(findRepo(o.repo), o.buildDir);
    std::error_code ec;
    const auto removed = fs::remove_all(folder, ec);
    if (ec) throw Error("bisect --clean: cannot remove " + folder + ": " + ec.message(), ExitCode::Failure);
    std::cout << (removed ? "removed " : "nothing to remove at ") << folder << "\n";
    return 0;
}

} // namespace

int BisectCommand::main(int argc, char** argv) {
    CLI::App app{"bench bisect: the first commit where a configuration's exact work, instructions or image "
                 "changed",
                 "bench bisect"};
    app.footer(kFooter);
    BisectOptions o;
    // Everything after `--` is the run's own options, handed to bench untouched.
    int own = argc;
    for (int i = 1; i < argc; ++i)
        if (std::string(argv[i]) == "--") {
            own = i;
            for (int k = i + 1; k < argc; ++k) o.runArgs.emplace_back(argv[k]);
            break;
        }
    app.add_option("good", o.good, "the commit whose signal is the reference");
    app.add_option("bad", o.bad, "a later commit (GOOD must be its ancestor)");
    app.add_option("-c,--config", o.config,
                   "a configuration of the perf gate's suite (results/ci/suite.json)");
    app.add_option("--signal", o.signal, "work, instructions or image")->capture_default_str();
    app.add_option("--repo", o.repo, "the repository (default: the checkout holding the working directory)");
    app.add_option("--suite", o.suite, "suite definition (default results/ci/suite.json)");
    app.add_option(
        "--build-dir", o.buildDir,
        "where the worktree and the kept build folder go (default $XDG_CACHE_HOME/shadowbench/bisect, "
        "else /var/tmp)");
    app.add_option("--jobs", o.jobs, "parallel build jobs (default: ninja's)")->check(CLI::Range(1, 1024));
    app.add_option("--ir-threshold", o.irThreshold,
                   "instructions: the relative change of Ir per frame that counts as changed")
        ->check(CLI::Range(1e-9, 1.0))
        ->capture_default_str();
    app.add_option("--json", o.json, "also write the result as JSON to this file");
    // The bench this command runs itself on the driver already; each commit's bench inherits it.
    DriverOption::add(app, o.driver);
    app.add_flag("--clean", o.clean,
                 "remove the build folder (alone: only that; after a bisection: at its end)");
    if (int code = parseCli(app, own, argv, "bench bisect"); code >= 0) return code;

    GitRepo::requireGit();
    if (o.clean && o.good.empty() && o.bad.empty()) return cleanOnly(o);
    if (o.good.empty() || o.bad.empty()) throw Error("bisect: give GOOD and BAD (bench bisect --help)");
    const GitRepo repo = findRepo(o.repo);
    const std::string good = repo.resolve(o.good), bad = repo.resolve(o.bad);
    if (good == bad) throw Error("bisect: GOOD and BAD are the same commit " + good.substr(0, 12));
    if (!repo.isAncestor(good, bad))
        throw Error("bisect: GOOD " + o.good + " is not an ancestor of BAD " + o.bad + " in " + repo.dir());
    auto [suite, config] = configuration(o);
    const BisectSignal signal(BisectSignal::parse(o.signal), suite, config, o.irThreshold);
    if (!o.json.empty()) AtomicFile::checkWritable(o.json, "--json"); // now, not after an hour of builds
    signal.requireTools();
    BisectWorkspace::requireBuildTools();

    const std::string folder = BisectWorkspace::folderFor(repo, o.buildDir);
    BisectResult result;
    {
        InterruptGuard guard;
        BisectWorkspace workspace(repo, folder, good);
        result = Bisection(repo, workspace, signal, o.jobs).run(good, bad, InterruptGuard::flag());
    } // the worktree's registration ends here, also when run() throws
    if (o.clean) fs::remove_all(folder);
    printResult(result, repo, signal);
    if (!o.json.empty())
        CsvWriter::writeText(o.json, result.toJson(o.signal, signal.benchArgs()).dump(2) + "\n");
    return result.outcome.kind == BisectOutcome::Kind::Found ? 0 : int(ExitCode::Failure);
}

} // namespace sb
