#include "bench/figures/FiguresCommand.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <unistd.h>

#include "bench/figures/FigureCatalog.h"
#include "bench/lib/bottleneck/BottleneckStudy.h"
#include "bench/lib/options/CliParse.h"
#include "bench/lib/options/DriverOption.h"
#include "bench/lib/output/RowExport.h"
#include "bench/lib/sweep/ChildProcess.h"
#include "bench/lib/sweep/SweepDefinition.h"
#include "bench/lib/sweep/SweepReport.h"
#include "bench/lib/sweep/SweepRunner.h"
#include "core/Error.h"
#include "core/Paths.h"

namespace sb {

namespace {

namespace fs = std::filesystem;

struct FiguresCli {
    std::string catalog, out, only;
    std::string driver; ///< acted on by BenchApp: the process already runs on it
    bool reduced = false, resume = false, plotOnly = false, list = false, noProgress = false;
};

/// Debian's python3 with matplotlib and pandas (the first python3 on PATH may lack them);
/// SHADOWBENCH_PYTHON overrides it.
std::string python() {
    const char* p = std::getenv("SHADOWBENCH_PYTHON");
    return p && *p ? p : "/usr/bin/python3";
}

/// Stops before minutes of measuring when the plots cannot be drawn: no interpreter, or one without
/// matplotlib and pandas (optional at run time: scripts/install-deps.sh's plot group installs them).
void requirePlotting() {
    const std::string interpreter = python();
    const std::string install =
        "apt-get install python3-matplotlib python3-pandas, or set SHADOWBENCH_PYTHON";
    if (access(interpreter.c_str(), X_OK) != 0)
        throw Error("bench figures: " + interpreter +
                        " is missing: tools/plot.py draws the figures with python3, "
                        "matplotlib and pandas (" +
                        install + ")",
                    ExitCode::Unsupported);
    const ChildExit probe =
        ChildProcess::run({interpreter, "-c", "import matplotlib, pandas"}, {}, [](const std::string&) {});
    if (!probe.ok())
        throw Error("bench figures: " + interpreter +
                        " cannot import matplotlib and pandas, which tools/plot.py "
                        "draws the figures with (" +
                        install + "): " + probe.stderrTail,
                    ExitCode::Unsupported);
}

bool selected(const FiguresCli& cli, const std::string& name) {
    if (cli.only.empty()) return true;
    for (const std::string& n : SweepDefinition::splitList(cli.only, "--only"))
        if (n == name) return true;
    return false;
}

/// Measures the figure's rows into dir/data.csv: through a partial file, renamed when the sweep is
/// complete, so an interrupted rerun never replaces the committed data with half of it. Returns false
/// when interrupted.
bool measure(const FigureDeclaration& f, const FiguresCli& cli, const std::string& catalog,
             const fs::path& dir, bool& failed) {
    const SweepPlan plan = f.plan(cli.reduced, catalog);
    SweepRunOptions options;
    options.csvPath = (dir / "data.partial.csv").string();
    options.resume = cli.resume;
    options.progress = !cli.noProgress;
    // A reduced run checks that every figure is produced, not what a frame costs: its rows say the GPU
    // timer is unchecked instead of calibrating it once per figure (about a second each at 512^2 and
    // 1024^2, most of a reduced figure's time).
    options.checkTimer = !cli.reduced;
    const SweepSummary summary = SweepRunner::run(plan, options);
    SweepReport::printSummary(std::cout, plan, options, summary);
    if (summary.interrupted) return false;
    failed = failed || summary.failed > 0;
    fs::rename(options.csvPath, dir / "data.csv");
    return true;
}

/// The table the plot reads: the rows, or for a bottleneck figure their classification.
fs::path plotInput(const FigureDeclaration& f, const fs::path& dir) {
    const fs::path data = dir / "data.csv";
    if (f.kind != FigureDeclaration::Kind::Bottleneck) return data;
    const fs::path classes = dir / "classes.csv";
    const std::vector<BottleneckEntry> entries = BottleneckStudy::analyse(CsvWriter::read(data.string()));
    CsvWriter::writeTable(classes.string(), BottleneckStudy::table(entries));
    BottleneckStudy::printTable(std::cout, entries);
    return classes;
}

void plot(const FigureDeclaration& f, const fs::path& input, const fs::path& dir) {
    const std::string script = Paths::findResource("tools/plot.py");
    if (script.empty()) throw Error("cannot find tools/plot.py", ExitCode::Failure);
    std::vector<std::string> argv{
        python(), script, f.plotKind, input.string(), "--out", (dir / "figure").string(), "--title", f.title};
    argv.insert(argv.end(), f.plotArgs.begin(), f.plotArgs.end());
    const ChildExit exit =
        ChildProcess::run(argv, {}, [](const std::string& line) { std::cout << line << "\n"; });
    if (!exit.ok())
        throw Error("figure '" + f.name + "': tools/plot.py failed (" + exit.describe() +
                        "): " + exit.stderrTail,
                    ExitCode::Failure);
}

void writeSummary(const FigureDeclaration& f, const fs::path& input, const fs::path& dir, bool reduced) {
    std::string text = "# " + f.title + "\n\n![" + f.name + "](figure.png)\n\n- Seed: " + f.seed +
                       "\n- Claim tested: " + f.claim + "\n- Regenerate: `bench figures --only " + f.name +
                       (reduced ? " --reduced" : "") + "`\n\nThe rows behind the figure (" +
                       input.filename().string() + "; `bench export " + input.filename().string() +
                       " --format md --all-columns` shows every column):\n\n" +
                       RowExport::toMarkdown(CsvWriter::read(input.string()));
    CsvWriter::writeText((dir / "summary.md").string(), text);
}

} // namespace

int FiguresCommand::main(int argc, char** argv) {
    CLI::App app{"bench figures: rerun the sweeps behind the reproduced figures and replot them",
                 "bench figures"};
    app.footer(R"(Examples:
  bench figures                          every figure into results/figures/<name>/ (minutes)
  bench figures --only instances_aircraft
  bench figures --reduced --out /tmp/f   the small variant of each (what CI runs)
  bench figures --plot-only              replot from the committed CSVs
  bench figures --list)");
    FiguresCli cli;
    app.add_option("--catalog", cli.catalog, "figure declarations (default results/figures/figures.json)");
    app.add_option("--out", cli.out,
                   "output folder (default: the catalog's folder; --reduced: figures-reduced)");
    app.add_option("--only", cli.only, "comma-separated figure names");
    app.add_flag("--reduced", cli.reduced, "few configurations at a small size, GPU timer unchecked (CI)");
    app.add_flag("--resume", cli.resume, "continue interrupted figure sweeps");
    app.add_flag("--plot-only", cli.plotOnly, "replot from the existing data.csv files");
    app.add_flag("--list", cli.list, "list the declared figures and exit");
    app.add_flag("--no-progress", cli.noProgress, "no progress bar on stderr");
    DriverOption::add(app, cli.driver);
    if (int code = parseCli(app, argc, argv, "bench figures"); code >= 0) return code;
    const std::string catalog = cli.catalog.empty() ? FigureCatalog::defaultPath() : cli.catalog;
    const std::vector<FigureDeclaration> figures = FigureCatalog::load(catalog);
    if (cli.list) {
        for (const FigureDeclaration& f : figures)
            std::cout << f.name << "  " << f.title << "\n    claim: " << f.claim << "\n";
        return 0;
    }
    const fs::path out = !cli.out.empty() ? fs::path(cli.out)
                         : cli.reduced    ? fs::path("figures-reduced")
                                          : fs::path(catalog).parent_path();
    requirePlotting();
    bool failed = false;
    size_t done = 0;
    for (const FigureDeclaration& f : figures) {
        if (!selected(cli, f.name)) continue;
        const fs::path dir = out / f.name;
        fs::create_directories(dir);
        std::cout << "== figure " << f.name << ": " << f.title << "\n";
        if (!cli.plotOnly && !measure(f, cli, catalog, dir, failed)) return 130;
        const fs::path input = plotInput(f, dir);
        plot(f, input, dir);
        writeSummary(f, input, dir, cli.reduced);
        ++done;
    }
    if (done == 0) throw Error("--only " + cli.only + ": no such figure (bench figures --list)");
    std::cout << done << " figure(s) written under " << out.string() << "\n";
    return failed ? int(ExitCode::Failure) : 0;
}

} // namespace sb
