#include "bench/bottleneck/BottleneckCommand.h"

#include <filesystem>
#include <iostream>

#include "bench/lib/bottleneck/BottleneckStudy.h"
#include "bench/lib/options/CliParse.h"
#include "bench/lib/options/DriverOption.h"
#include "bench/lib/output/RowExport.h"
#include "bench/lib/sweep/SweepOptions.h"
#include "bench/lib/sweep/SweepReport.h"
#include "bench/lib/sweep/SweepRunner.h"
#include "core/Error.h"

namespace sb {

namespace {

const char* kFooter = R"(Perturbations (each its own worker process, techniques interleaved inside):
  baseline; submit_immediate (CPU up; submit_retained from an immediate base; with --api vulkan, which
  has no immediate mode, submit_instanced: CPU down); scale_x10_near and
  scale_x0.01 (fill up/down at equal vertex count, thesis section 6.2); size_half, size_double (fill
  only); tess_half, tess_double (vertex only); lp_no_rast (Mesa llvmpipe, lavapipe: rasteriser off).
Each technique is classified from a fit of frame time against the loads measured in an untimed
census frame: CPU load = GL calls issued; vertex load = primitives submitted (not vertex shader
invocations, which the submission mode changes by itself); fill load = fragment shader invocations.
The stage with >= 50% of the frame time names the bottleneck.

Examples:
  bench bottleneck -t none -t shadowmap --instances 100 --csv bn.csv
  bench bottleneck -t shadowmap --scene aircraft,teapot --frames 10 --csv bn.csv --resume
  bench bottleneck --from bn.csv                       classify rows measured before
  bench bottleneck -t synthetic:fragment_iterations=200:draw_scene=false --scene sphere_plane --csv f.csv
  bench bottleneck --api vulkan -t shadowmap --scene aircraft --csv vk.csv   the Vulkan forms on lavapipe

Writes the measurement rows to --csv and the classification to --classes (default: <csv>_classes.csv).)";

std::string defaultClassesPath(const std::string& csv) {
    std::filesystem::path p(csv);
    return (p.parent_path() / (p.stem().string() + "_classes.csv")).string();
}

int classify(const std::string& csv, const std::string& classes, RowFormat format) {
    const std::vector<BottleneckEntry> entries = BottleneckStudy::analyse(CsvWriter::read(csv));
    const CsvTable table = BottleneckStudy::table(entries);
    CsvWriter::writeTable(classes, table);
    std::ostream& log = format == RowFormat::Console ? std::cout : std::cerr;
    BottleneckStudy::printTable(log, entries);
    log << "classification written to " << classes << "\n";
    // CSV and JSON carry every column of the classes CSV; Markdown is for people and shows what the
    // console table shows (the curated columns of result rows have no class or share at all).
    if (format == RowFormat::Markdown)
        std::cout << RowExport::toMarkdown(BottleneckStudy::summary(table), true);
    else if (format != RowFormat::Console)
        std::cout << RowExport::format(table, format);
    return 0;
}

} // namespace

int BottleneckCommand::main(int argc, char** argv) {
    CLI::App app{"bench bottleneck: is each technique CPU-, vertex- or fill-limited here?",
                 "bench bottleneck"};
    app.footer(kFooter);
    app.get_formatter()->column_width(34);
    SweepOptions axes;
    std::string csv, classes, from, shard = "1/1", format = "console";
    bool resume = false, noProgress = false;
    app.add_option("--csv", csv, "measurement rows go here (required unless --from)");
    app.add_option("--classes", classes, "the classification CSV (default <csv>_classes.csv)");
    app.add_option("--from", from, "classify the rows of this CSV instead of measuring");
    app.add_flag("--resume", resume, "continue a study in --csv");
    app.add_option("--shard", shard, "run slice i of N (i/N); classify after bench merge")
        ->capture_default_str();
    app.add_flag("--no-progress", noProgress, "no progress bar on stderr");
    app.add_option("--format", format, "stdout: " + rowFormatChoices() + " (the classification)")
        ->capture_default_str();
    axes.add(app);
    std::string api = "gl";
    app.add_option("--api", api, "gl or vulkan: the API every run of the study draws with")
        ->check(CLI::IsMember({"gl", "vulkan"}))
        ->capture_default_str();
    std::string driver; // acted on by BenchApp: the process already runs on it
    DriverOption::add(app, driver);
    if (int code = parseCli(app, argc, argv, "bench bottleneck"); code >= 0) return code;
    const RowFormat rowFormat = parseRowFormat(format);
    // Checked before the study runs: the classification has shares and ratios, no frame time to chart.
    if (rowFormat == RowFormat::GoogleBenchmark || rowFormat == RowFormat::GithubBenchmark)
        throw Error("--format " + format +
                    ": the classification has no frame times; chart the study's "
                    "rows with bench export CSV --format " +
                    format);
    if (!from.empty()) return classify(from, classes.empty() ? defaultClassesPath(from) : classes, rowFormat);
    if (csv.empty())
        throw Error("bench bottleneck: --csv FILE is required (where the rows go), or --from FILE");

    SweepDefinition definition;
    definition.name = "bottleneck";
    // Nine perturbations per technique: fewer frames than a single run by default (the command line's
    // --frames, --seconds or --warmup replaces these, as it replaces a sweep file's).
    definition.commonArgs = {"--frames", "20", "--warmup", "3"};
    axes.applyTo(definition);
    // Every run draws with the API asked for: the workers take it from the common arguments, and the
    // plan picks the submission switch the API can express.
    if (api == "vulkan") definition.commonArgs.insert(definition.commonArgs.end(), {"--api", "vulkan"});
    const SweepPlan plan = BottleneckStudy::plan(definition);
    SweepRunOptions options;
    options.csvPath = csv;
    options.resume = resume;
    std::tie(options.shard, options.shardCount) = parseShard(shard);
    options.progress = !noProgress;
    const SweepSummary summary = SweepRunner::run(plan, options);
    std::ostream& log = rowFormat == RowFormat::Console ? std::cout : std::cerr;
    SweepReport::printSummary(log, plan, options, summary);
    if (summary.interrupted) return 130;
    if (options.shardCount > 1) {
        log << "shard done: merge the shards (bench merge) and classify with bench bottleneck --from\n";
        return summary.failed ? int(ExitCode::Failure) : 0;
    }
    classify(csv, classes.empty() ? defaultClassesPath(csv) : classes, rowFormat);
    return summary.failed ? int(ExitCode::Failure) : 0;
}

} // namespace sb
