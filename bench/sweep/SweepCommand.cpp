#include "bench/sweep/SweepCommand.h"
#include "bench/lib/options/DriverOption.h"

#include <cstdint>
#include <cstdio>
#include <iostream>
#include <optional>

#include "bench/lib/options/CliParse.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/output/RowExport.h"
#include "bench/lib/output/StandardStreams.h"
#include "bench/lib/sweep/SweepDefinition.h"
#include "bench/lib/sweep/SweepOptions.h"
#include "bench/lib/sweep/SweepReport.h"
#include "bench/lib/sweep/SweepRunner.h"
#include "core/Error.h"

namespace sb {

namespace {

const char* kFooter =
    R"(Every combination of the axes is one group, run in its own worker process; inside it the
techniques are measured in rounds (--repeat) next to each other. Rows go to --csv as they finish.

Examples:
  bench sweep -t none -t shadowmap --instances 1,50,100,200 --csv inst.csv
  bench sweep sweeps/submission.json --csv sub.csv
  bench sweep -t shadowmap:resolution=512,1024,2048 --submit retained,immediate --csv r.csv
  bench sweep sweeps/submission.json --csv sub.csv --resume         continue an interrupted sweep
  bench sweep sweeps/submission.json --csv sub.csv --resume --retry-failed
                                                    continue it and run the failed configurations again
  bench sweep sweeps/submission.json --shard 2/4 --csv part2.csv     one of four slices
  bench sweep sweeps/submission.json --shard 2/4 --csv part2.csv --resume --retry-failed
                                                    a requeued Slurm task: its slice, failures retried
  parallel bench sweep s.json --shard {}/2 --csv part{}.csv ::: 1 2 && bench merge -o all.csv part1.csv part2.csv
  bench sweep s.json --dry-run                                       list the configurations only

One process writes a shard of a --csv at a time: it holds the lock <csv>.shard-<i>-of-<N>.lock for
the whole run (removed at the end; one left by a process that died blocks nothing), and a second run of
the same shard is refused with the holder's host, pid, Slurm job and start time. Rows record where they
ran: host, slurm_job_id, slurm_array_task_id, and hw_threads, the CPUs the process was given.

Exit codes: 0 ok, 1 some configurations failed (rows with status=failed say why) or another process is
writing this shard of --csv (nothing written), 2 bad input (also: --retry-failed without --resume, a
--csv of another sweep, or --resume of a file written with another --shard split, e.g. 1/4 rows
resumed as --shard 1/2), 130 interrupted (run the same command with --resume to continue).)";

struct SweepCli {
    std::string file, csv, shard = "1/1", format = "console", name, mode;
    bool resume = false, retryFailed = false, dryRun = false, noProgress = false, qualitySweep = false;
    std::optional<int64_t> maxConfigs; ///< set only when given: no typed value means "the default"
    std::string driver;                ///< acted on by BenchApp (the process already runs on it)
    SweepOptions axes;
};

} // namespace

int SweepCommand::main(int argc, char** argv) {
    CLI::App app{"bench sweep: measure every combination of the given axes", "bench sweep"};
    app.footer(kFooter);
    app.get_formatter()->column_width(34);
    SweepCli cli;
    app.add_option("file", cli.file, "sweep definition (JSON; see README 'Sweep configurations')");
    app.add_option("--csv", cli.csv, "rows go here, appended as they finish (required unless --dry-run)");
    cli.axes.add(app);
    DriverOption::add(app, cli.driver);
    app.add_option("--mode", cli.mode, "measure (default) or accuracy (judge against the reference too)");
    app.add_flag("--quality-sweep", cli.qualitySweep, "accuracy: walk each technique's quality knobs");
    app.add_option("--name", cli.name, "sweep name recorded in every row (default: the file's stem)");
    app.add_option_function<int64_t>(
        "--max-configs", [&cli](int64_t limit) { cli.maxConfigs = limit; },
        "refuse sweeps of more configurations (rows) than this (default 10000)");
    app.add_flag("--resume", cli.resume, "continue the sweep in --csv, skipping the rows it already has");
    app.add_flag("--retry-failed", cli.retryFailed,
                 "with --resume: run the configurations whose rows failed again, replacing those rows");
    app.add_option("--shard", cli.shard, "run slice i of N (i/N) of the combinations")->capture_default_str();
    app.add_flag("--dry-run", cli.dryRun, "print the configurations and exit");
    app.add_flag("--no-progress", cli.noProgress, "no progress bar on stderr");
    app.add_option("--format", cli.format,
                   "stdout at the end: " + rowFormatChoices() + " (this shard's rows)")
        ->capture_default_str();
    if (int code = parseCli(app, argc, argv, "bench sweep"); code >= 0) return code;
    // Retrying is a way of continuing a sweep: without --resume the file's rows would be refused anyway.
    if (cli.retryFailed && !cli.resume)
        throw Error("--retry-failed needs --resume: it runs the failed configurations of the sweep in --csv "
                    "again; add --resume");

    const RowFormat format = parseRowFormat(cli.format);
    if (format != RowFormat::Console) StandardStreams::requireStdout("--format " + cli.format);
    const auto [shard, shardCount] = parseShard(cli.shard);
    SweepDefinition definition =
        cli.file.empty() ? SweepDefinition{} : SweepDefinition::fromJsonFile(cli.file);
    cli.axes.applyTo(definition);
    if (!cli.name.empty()) definition.name = cli.name;
    if (cli.qualitySweep) definition.qualitySweep = true;
    if (cli.maxConfigs) {
        if (*cli.maxConfigs < 1)
            throw Error("--max-configs " + std::to_string(*cli.maxConfigs) + ": expected 1.." +
                        std::to_string(INT64_MAX));
        definition.maxConfigs = uint64_t(*cli.maxConfigs);
    }
    if (!cli.mode.empty()) {
        if (cli.mode != "measure" && cli.mode != "accuracy")
            throw Error("--mode " + cli.mode + ": expected measure or accuracy");
        definition.mode = cli.mode == "accuracy" ? SweepPlan::Mode::Accuracy : SweepPlan::Mode::Measure;
    }
    const SweepPlan plan = definition.expand();
    std::ostream& log = format == RowFormat::Console ? std::cout : std::cerr;
    if (cli.dryRun) {
        SweepReport::printPlan(log, plan, shard, shardCount);
        return 0;
    }
    if (cli.csv.empty()) throw Error("bench sweep: --csv FILE is required (where the rows go)");
    SweepRunOptions options;
    options.csvPath = cli.csv;
    options.resume = cli.resume;
    options.retryFailed = cli.retryFailed;
    options.shard = shard;
    options.shardCount = shardCount;
    options.progress = !cli.noProgress;
    const SweepSummary summary = SweepRunner::run(plan, options);
    SweepReport::printSummary(log, plan, options, summary);
    if (format != RowFormat::Console)
        std::cout << RowExport::format(SweepReport::shardRows(plan, options), format);
    if (format != RowFormat::Console) StandardStreams::finishStdout("--format " + cli.format);
    if (summary.interrupted) return 130;
    return summary.failed ? int(ExitCode::Failure) : 0;
}

} // namespace sb
