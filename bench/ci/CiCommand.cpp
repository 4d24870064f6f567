#include "bench/ci/CiCommand.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "bench/lib/gate/BaselineUpdate.h"
#include "bench/lib/gate/CiSuite.h"
#include "bench/lib/gate/GateReport.h"
#include "bench/lib/gate/InstructionLayer.h"
#include "bench/lib/gate/SuiteRunner.h"
#include "bench/lib/gate/WallLayer.h"
#include "bench/lib/gate/WorkGate.h"
#include "bench/lib/options/CliParse.h"
#include "bench/lib/options/DriverOption.h"
#include "bench/lib/output/AtomicFile.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/output/DashboardExport.h"
#include "bench/lib/output/ProgressBar.h"
#include "bench/lib/output/ResultColumns.h"
#include "bench/lib/sweep/ChildProcess.h"
#include "core/DriverTable.h"
#include "core/Error.h"
#include "core/JsonReader.h"
#include "core/Paths.h"

namespace sb {

namespace {

namespace fs = std::filesystem;

constexpr const char* kFooter = R"(Examples:
  bench ci                                      the committed suite against the committed baseline
  bench ci --quick                              layer A only (exact work; seconds)
  bench ci --update                             after an intended change: rewrite results/ci/baseline/
  bench ci --base-bench /tmp/base/bench         this build against another build, all three layers
  bench ci --base-env LP_NUM_THREADS=2 --head-env LP_NUM_THREADS=1 --layers A,C   a threads A/B
  bench ci --base-driver system --head-driver mesa-25.0.7 --layers A   a driver A/B
  bench --driver mesa-25.0.7 ci --quick          the gate on another driver, against baseline/mesa-25.0.7/
  bench --driver mesa-25.0.7 ci --layers B --driver-bound   layer B of what only that driver can run
  SHADOWBENCH_INJECT=extra_fullscreen_pass bench ci --layers A   the proof: a known regression

A configuration the suite binds to drivers ("drivers": a technique whose form needs what only they
offer) runs on those only; elsewhere the report says it was not run and why.
--update of some configurations (--configs, --driver-bound) keeps the baseline's other rows.

Layers: A exact work per pass (any increase fails; a decrease passes and asks for --update; across two
drivers the application's work must match exactly and the driver's is reported with both values),
B instructions per frame under valgrind (fails beyond max(0.5%, the A/A pair)), C wall time
interleaved with an A/A control (fails beyond max(5%, the control's noise) at p < alpha).
Exit codes: 0 pass, 1 a gating layer failed, 2 bad input, 3 the machine lacks what a layer needs.)";

/// The cell of a configuration bound to drivers this run is not on (CiConfig::drivers).
constexpr const char* kNotRun = "NOT RUN";

struct CiOptions {
    std::string suitePath, baselineDir, outDir = "ci-out";
    std::string layers = "A,B,C", advisory;
    bool update = false, quick = false, driverBound = false;
    std::vector<std::string> configs, baseEnv, headEnv;
    std::string baseBench, headBench;
    std::string driver, baseDriver, headDriver; ///< --driver is acted on by BenchApp
    WallLayerOptions wall;
    std::string scheme = "abba";
};

std::vector<std::pair<std::string, std::string>> parseEnv(const std::vector<std::string>& items,
                                                          const char* option) {
    std::vector<std::pair<std::string, std::string>> out;
    for (const std::string& item : items) {
        const size_t eq = item.find('=');
        if (eq == 0 || eq == std::string::npos)
            throw Error(std::string(option) + " " + item + ": expected NAME=VALUE");
        out.emplace_back(item.substr(0, eq), item.substr(eq + 1));
    }
    return out;
}

bool hasLayer(const std::string& layers, char layer) {
    return layers.find(layer) != std::string::npos;
}

/// Adds the column ir_per_frame to layer A's rows from layer B's record ({"configs": {name: {...}}}),
/// matching on ci_config; configurations layer B did not count keep an empty cell.
void joinInstructions(CsvTable& rows, const nlohmann::json& record) {
    if (rows.rows.empty() || !record.contains("configs")) return;
    const auto config = std::find(rows.header.begin(), rows.header.end(), col::kCiConfig);
    if (config == rows.header.end()) return;
    const size_t at = size_t(config - rows.header.begin());
    rows.header.push_back("ir_per_frame");
    for (auto& row : rows.rows) {
        const auto& configs = record["configs"];
        const bool counted = configs.contains(row[at]) && configs[row[at]].contains("ir_per_frame");
        char text[64] = "";
        if (counted) std::snprintf(text, sizeof text, "%.1f", configs[row[at]]["ir_per_frame"].get<double>());
        row.push_back(text);
    }
}

std::string defaultPath(const std::string& given, const char* relative) {
    if (!given.empty()) return given;
    const std::string found = Paths::findResource(relative);
    if (found.empty())
        throw Error(std::string("cannot find ") + relative + " (give its path)", ExitCode::BadInput);
    return found;
}

/// Layer A's rows of one side: every selected configuration's census.
CsvTable workRows(const CiSuite& suite, const std::vector<const CiConfig*>& configs, const CiSide& side) {
    std::vector<CsvRow> rows;
    std::cerr << "ci: layer A, exact work of " << configs.size() << " configurations (" << side.describe()
              << ")\n";
    ProgressBar bar(stderr, configs.size(), 0);
    for (const CiConfig* c : configs)
        rows.push_back(bar.step("work " + c->name + " (" + side.describe() + ")", [&] {
            return SuiteRunner::run(suite, *c, side, {suite.work.frames, suite.work.warmup, {}, {}});
        }));
    bar.close();
    return CsvWriter::toTable(rows);
}

/// Layer A's verdict, details and each configuration's cell (WorkGate.h: nothing uncompared reads PASS;
/// across drivers the application's work is judged and the driver's reported).
GateLayer judgeWork(const WorkComparison& w, GateReport& report, const std::string& baseName) {
    for (GateConfigRow& row : report.rows)
        if (row.work.verdict != kNotRun) row.work = w.cell(row.config);
    return WorkGate::layer(w, baseName);
}

/// What the committed baseline keeps of layer A's rows: the configuration's identity and its exact
/// counts, no times or timestamps, so that its diff in review shows only work that changed. The identity
/// includes the driver on both APIs (Vulkan rows name it in gl_vendor only), so that layer A can tell a
/// head on another driver from one on the baseline's.
CsvTable baselineColumns(const CsvTable& rows) {
    static const std::vector<std::string> kKeep = {
        col::kCiConfig, col::kStatus,    col::kApi,           col::kRenderer,  col::kGlVersion,
        col::kGlVendor, col::kDriver,    col::kDriverVersion, col::kTechnique, col::kProperties,
        col::kScene,    col::kInstances, col::kSubmit,        col::kBackFaces, col::kWidth,
        col::kHeight,   col::kLights,    col::kLighting};
    std::vector<size_t> keep;
    for (size_t c = 0; c < rows.header.size(); ++c)
        if (std::find(kKeep.begin(), kKeep.end(), rows.header[c]) != kKeep.end() ||
            WorkGate::isWorkColumn(rows.header[c]))
            keep.push_back(c);
    CsvTable out;
    for (size_t c : keep) out.header.push_back(rows.header[c]);
    for (const auto& row : rows.rows) {
        out.rows.emplace_back();
        for (size_t c : keep) out.rows.back().push_back(row[c]);
    }
    return out;
}

/// The baseline's rows of the configurations run now (--configs runs a subset).
CsvTable onlyConfigs(CsvTable table, const std::vector<const CiConfig*>& configs) {
    auto column = std::find(table.header.begin(), table.header.end(), col::kCiConfig);
    if (column == table.header.end()) return table;
    const size_t c = size_t(column - table.header.begin());
    std::erase_if(table.rows, [&](const std::vector<std::string>& row) {
        return std::none_of(configs.begin(), configs.end(),
                            [&](const CiConfig* k) { return k->name == row[c]; });
    });
    return table;
}

/// A side's variables: its driver's (core/DriverTable.h; none when `driver` is empty) then --*-env's,
/// which may override them.
std::vector<std::pair<std::string, std::string>>
sideEnvironment(const std::string& driver, const std::vector<std::string>& env, const char* envOption) {
    std::vector<std::pair<std::string, std::string>> out;
    if (!driver.empty()) out = DriverTable::childEnvironment(DriverTable::resolve(driver));
    for (auto& item : parseEnv(env, envOption)) out.push_back(std::move(item));
    return out;
}

/// The committed baseline of the driver the head runs on: results/ci/baseline/ for the system driver,
/// baseline/<name>/ for another named one (each driver rasterises, and so counts, its own way). A
/// driver given by its prefix has no committed baseline: --baseline names one.
std::string driverBaseline(const std::string& root, const std::string& driver) {
    if (driver == "system") return root;
    const auto named = DriverTable::names();
    if (std::find(named.begin(), named.end(), driver) == named.end())
        throw Error("bench ci on the driver " + driver +
                    ": no committed baseline for a driver outside the table; give --baseline DIR (write "
                    "one with bench ci --update --baseline DIR)");
    return (fs::path(root) / driver).string();
}

std::string joinArgs(int argc, char** argv) {
    std::string out = "bench";
    for (int i = 0; i < argc; ++i) out += std::string(" ") + argv[i];
    return out;
}

void writeRows(const std::string& path, const CsvTable& table) {
    if (!table.rows.empty()) CsvWriter::writeTable(path, table);
}

} // namespace

int CiCommand::main(int argc, char** argv) {
    CLI::App app{"bench ci: the perf gate on exact work, instructions per frame and wall time", "bench ci"};
    app.footer(kFooter);
    CiOptions o;
    app.add_option("--suite", o.suitePath, "suite definition (default results/ci/suite.json)");
    app.add_option("--baseline", o.baselineDir, "committed baseline folder (default results/ci/baseline)");
    app.add_option("--out", o.outDir, "where report.md, report.json and the rows go")->capture_default_str();
    app.add_option("--layers", o.layers, "layers to run, from A,B,C")->capture_default_str();
    app.add_option("--advisory", o.advisory, "layers reported but never failing the gate (e.g. C)");
    app.add_flag("--quick", o.quick, "layer A only");
    app.add_flag("--update", o.update,
                 "rewrite the baseline from this build (layers A and B) instead of judging");
    app.add_option("--configs", o.configs, "only these configurations (comma-separated)")->delimiter(',');
    app.add_flag("--driver-bound", o.driverBound,
                 "only the configurations the suite binds to the driver this run is on (its \"drivers\"): "
                 "what no other driver can run");
    app.add_option("--base-bench", o.baseBench, "the base build's bench binary (measured now, interleaved)");
    app.add_option("--head-bench", o.headBench, "the head's bench binary (default: this one)");
    app.add_option("--base-env", o.baseEnv, "NAME=VALUE for the base's runs (repeatable)");
    app.add_option("--head-env", o.headEnv, "NAME=VALUE for the head's runs (repeatable)");
    DriverOption::add(app, o.driver);
    app.add_option("--base-driver", o.baseDriver,
                   "the base's runs on this driver (as --driver; a driver A/B)");
    app.add_option("--head-driver", o.headDriver, "the head's runs on this driver (as --driver)");
    app.add_option("--rounds", o.wall.rounds, "layer C rounds (default: the suite's)")
        ->check(CLI::Range(2, 1000));
    app.add_option("--seed", o.wall.seed, "layer C schedule seed (random scheme)");
    app.add_option("--scheme", o.scheme, "layer C order per round: abba or random")->capture_default_str();
    app.add_option("--alpha", o.wall.familyAlpha, "layer C family-wise false-alarm rate per run")
        ->check(CLI::Range(1e-9, 0.5))
        ->capture_default_str();
    app.add_option("--floor", o.wall.floor, "layer C: the smallest slowdown that may fail (fraction)")
        ->check(CLI::Range(0.0, 10.0))
        ->capture_default_str();
    if (int code = parseCli(app, argc, argv, "bench ci"); code >= 0) return code;
    WallLayer::checkThresholds(o.wall.familyAlpha, o.wall.floor);
    // Before any configuration runs: a mistyped binary would otherwise fail minutes later, as exit 1.
    for (const auto& [option, path] :
         {std::pair{"--base-bench", o.baseBench}, {"--head-bench", o.headBench}}) {
        std::error_code ec;
        if (!path.empty() && !fs::is_regular_file(path, ec))
            throw Error(std::string(option) + " " + path + ": no such file");
    }
    if (o.quick) o.layers = "A";
    for (char c : o.layers + o.advisory)
        if (c != ',' && c != 'A' && c != 'B' && c != 'C')
            throw Error("--layers/--advisory: '" + std::string(1, c) + "' is not a layer (A, B, C)");
    if (o.scheme != "abba" && o.scheme != "random") throw Error("--scheme " + o.scheme + ": abba or random");
    o.wall.scheme = o.scheme == "abba" ? ci::Scheme::Abba : ci::Scheme::Random;

    const CiSuite suite = CiSuite::load(defaultPath(o.suitePath, "results/ci/suite.json"));
    if (!app.count("--rounds")) o.wall.rounds = suite.wall.rounds;
    const std::string headDriver =
        o.headDriver.empty() ? DriverTable::current() : DriverTable::resolve(o.headDriver).name;
    const std::string baselineDir =
        o.baselineDir.empty()
            ? driverBaseline(fs::path(suite.path).parent_path().append("baseline").string(), headDriver)
            : o.baselineDir;
    const std::string baselineWork = (fs::path(baselineDir) / "work.csv").string(); ///< layer A's
    const CiSide head{"head", o.headBench.empty() ? ChildProcess::selfExecutable() : o.headBench,
                      sideEnvironment(o.headDriver, o.headEnv, "--head-env")};
    std::optional<CiSide> base;
    if (!o.baseBench.empty() || !o.baseEnv.empty() || !o.baseDriver.empty())
        base = CiSide{"base", o.baseBench.empty() ? head.bench : o.baseBench,
                      sideEnvironment(o.baseDriver, o.baseEnv, "--base-env")};
    if (o.update && base)
        throw Error("--update writes the head's baseline; it takes no --base-bench/--base-env/--base-driver");
    // The drivers the runs are on: a configuration bound to drivers runs only where every side can run it.
    std::vector<std::string> drivers{headDriver};
    if (base)
        drivers.push_back(o.baseDriver.empty() ? DriverTable::current()
                                               : DriverTable::resolve(o.baseDriver).name);
    for (const std::string& name : o.configs)
        for (const std::string& d : drivers)
            if (!suite.config(name).runsOn(d))
                throw Error("--configs " + name + ": not on the driver " + d + ", it " +
                                suite.config(name).notRunReason() + " (run it with bench --driver " +
                                suite.config(name).drivers.front() + " ci)",
                            ExitCode::Unsupported);
    auto select = [&](const CiLayerRuns& layer) {
        return suite.selectOn(layer, o.configs, drivers, o.driverBound);
    };
    if (o.driverBound && select({}).empty())
        throw Error("--driver-bound: no configuration of " + suite.path + " is bound to the driver " +
                    headDriver);
    // A missing committed baseline is bad input, said before the suite runs rather than after it.
    if (!o.update && !base && hasLayer(o.layers, 'A') && !fs::exists(baselineWork))
        throw Error("no committed baseline " + baselineWork + " (write one with bench ci --update" +
                    (headDriver == "system" ? std::string() : " --driver " + headDriver) + ")");
    fs::create_directories(o.outDir);
    AtomicFile::checkWritable((fs::path(o.outDir) / "report.md").string(), "the report");

    GateReport report;
    report.title = "shadowbench perf gate";
    report.reproduce = joinArgs(argc, argv);
    report.about.push_back("suite " + suite.path + " (" + std::to_string(suite.configs.size()) +
                           " configurations)");
    report.about.push_back("head: " + head.describe() + " " + head.bench);
    report.about.push_back(base ? "base: " + base->describe() + " " + base->bench + ", measured now"
                                : "base: the committed baseline " + baselineDir);
    const std::vector<const CiConfig*> runs = select({});
    for (const CiConfig* c : suite.select({}, o.configs)) {
        if (std::find(runs.begin(), runs.end(), c) != runs.end()) {
            report.rows.push_back({c->name, c->bound, {}, {}, {}});
            continue;
        }
        // A configuration another driver is to run: listed with why, never a silent gap.
        for (const std::string& d : drivers)
            if (!c->runsOn(d)) {
                report.rows.push_back({c->name, c->bound, {"not run on the driver " + d, kNotRun}, {}, {}});
                report.about.push_back(c->name + " not run on the driver " + d + ": " + c->notRunReason());
                break;
            }
    }
    auto row = [&](const std::string& name) -> GateConfigRow& {
        for (GateConfigRow& r : report.rows)
            if (r.config == name) return r;
        throw Error("no report row " + name, ExitCode::Failure);
    };

    CsvTable dashboardRows; // layer A's rows, with layer B's Ir per frame joined in: the dashboard files
    // --update writes the baseline files only once every layer it updates has succeeded: a layer that
    // throws (valgrind unable to run, a configuration failing) leaves the committed baseline as it was,
    // never half rewritten.
    std::vector<std::pair<std::string, std::string>> baselineFiles; ///< path, text
    std::vector<std::string> baselineNotes;
    if (hasLayer(o.layers, 'A')) {
        const auto configs = select(suite.work);
        const CsvTable headRows = workRows(suite, configs, head);
        dashboardRows = headRows;
        writeRows((fs::path(o.outDir) / "work.csv").string(), headRows);
        if (o.update) {
            const CsvTable fresh = baselineColumns(headRows);
            const CsvTable merged = fs::exists(baselineWork)
                                        ? BaselineUpdate::work(CsvWriter::read(baselineWork), fresh,
                                                               suite.selectOn(suite.work, {}, drivers, false))
                                        : fresh;
            baselineFiles.emplace_back(baselineWork, CsvWriter::serialize(merged));
            baselineNotes.push_back("ci: layer A baseline rewritten: " + baselineWork + " (" +
                                    std::to_string(headRows.rows.size()) + " configurations measured, " +
                                    std::to_string(merged.rows.size() - fresh.rows.size()) +
                                    " kept as they were)");
        } else {
            const CsvTable baseRows =
                base ? workRows(suite, configs, *base) : onlyConfigs(CsvWriter::read(baselineWork), configs);
            if (base) writeRows((fs::path(o.outDir) / "work_base.csv").string(), baseRows);
            GateLayer layer =
                judgeWork(WorkGate::compare(baseRows, headRows), report, base ? "base" : "baseline");
            layer.advisory = hasLayer(o.advisory, 'A');
            report.layers.push_back(layer);
        }
    }
    if (hasLayer(o.layers, 'B')) {
        const auto configs = select(suite.instructions);
        const std::string recordPath = (fs::path(baselineDir) / "instructions.json").string();
        if (!configs.empty()) {
            nlohmann::json committed;
            if (!base && fs::exists(recordPath))
                committed = JsonReader::parse(Paths::readTextFile(recordPath), recordPath);
            InstructionLayerResult r =
                InstructionLayer::run(suite, configs, base, head, o.update ? nlohmann::json() : committed,
                                      (fs::path(o.outDir) / "callgrind").string());
            CsvWriter::writeText((fs::path(o.outDir) / "instructions.json").string(),
                                 r.record.dump(2) + "\n");
            joinInstructions(dashboardRows, r.record);
            if (o.update) {
                const nlohmann::json record = BaselineUpdate::instructions(
                    committed, r.record, suite.selectOn(suite.instructions, {}, drivers, false), recordPath);
                baselineFiles.emplace_back(recordPath, record.dump(2) + "\n");
                baselineNotes.push_back("ci: layer B baseline rewritten: " + recordPath + " (" +
                                        std::to_string(configs.size()) + " configurations counted, " +
                                        std::to_string(record["configs"].size() - configs.size()) +
                                        " kept as they were)");
            } else {
                r.layer.advisory = hasLayer(o.advisory, 'B');
                for (const auto& [name, cell] : r.cells) row(name).instructions = cell;
                report.layers.push_back(r.layer);
            }
        }
    }
    if (hasLayer(o.layers, 'C') && !o.update) {
        const auto configs = select(suite.wall);
        if (!configs.empty()) {
            WallLayerResult r = WallLayer::run(suite, configs, base, head, o.wall);
            r.layer.advisory = hasLayer(o.advisory, 'C');
            for (const auto& [name, cell] : r.cells) row(name).wall = cell;
            writeRows((fs::path(o.outDir) / "wall.csv").string(), CsvWriter::toTable(r.runs));
            report.layers.push_back(r.layer);
        }
    }
    if (o.update) {
        fs::create_directories(baselineDir);
        for (const auto& [path, text] : baselineFiles) CsvWriter::writeText(path, text);
        for (const std::string& note : baselineNotes) std::cout << note << "\n";
        return 0;
    }
    const std::string md = report.markdown();
    CsvWriter::writeText((fs::path(o.outDir) / "report.md").string(), md);
    CsvWriter::writeText((fs::path(o.outDir) / "report.json").string(), report.json().dump(2) + "\n");
    if (!dashboardRows.rows.empty()) {
        // The gate's numbers in the formats dashboards chart (bench/lib/output/DashboardExport.h).
        CsvWriter::writeText((fs::path(o.outDir) / "gbench.json").string(),
                             DashboardExport::googleBenchmark(dashboardRows));
        CsvWriter::writeText((fs::path(o.outDir) / "gh-benchmark.json").string(),
                             DashboardExport::githubActionBenchmark(dashboardRows));
    }
    std::cout << md;
    return report.failed() ? int(ExitCode::Failure) : 0;
}

} // namespace sb
