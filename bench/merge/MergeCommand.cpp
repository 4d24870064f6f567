#include "bench/merge/MergeCommand.h"

#include <algorithm>
#include <cctype>
#include <iostream>
#include <string>

#include "bench/lib/options/CliParse.h"
#include "bench/lib/output/CsvMerge.h"
#include "core/Error.h"

namespace sb {

namespace {

/// `s` as one word for the shell: as it is when it holds nothing the shell would read, else quoted.
std::string shellWord(const std::string& s) {
    const bool plain = !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) ||
               std::string("_./+-=:,@%").find(c) != std::string::npos;
    });
    if (plain) return s;
    std::string quoted = "'";
    for (char c : s) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

std::string shardName(const MergeReport& r, size_t shard) {
    return std::to_string(shard) + "/" + std::to_string(r.shardCount);
}

void printSummary(const MergeReport& r, const std::string& output) {
    std::cout << (r.written ? "merged " : "read ") << r.files << " files of sweep " << r.sweepId;
    if (!r.sweepName.empty()) std::cout << " ('" << r.sweepName << "')";
    std::cout << ": " << r.rows << " rows of " << r.configs << " configurations";
    if (r.failedRows) std::cout << " (" << r.failedRows << " failed)";
    if (r.unsupportedRows) std::cout << ", " << r.unsupportedRows << " unsupported here";
    if (r.missingCount) std::cout << ", " << r.missingCount << " missing";
    std::cout << (r.written ? " -> " + output : "; nothing written") << "\n";
    // Many nodes of one kind are normal on a cluster; the count says where the rows ran.
    if (r.hosts) std::cout << "rows from " << *r.hosts << (*r.hosts == 1 ? " host" : " hosts") << "\n";
}

void printMixtures(const MergeReport& r) {
    if (r.timerVerdicts.size() > 1) {
        std::cout << "warning: rows carry different GPU-timer verdicts:";
        for (const auto& [verdict, rows] : r.timerVerdicts) std::cout << " " << verdict << " " << rows;
        std::cout << " (compare GPU columns only within one verdict)\n";
    }
    if (r.mixtures.empty()) return;
    std::cout << "warning: rows of different measurements merged (--allow-mixed); compare rows only within "
                 "one value of each:\n";
    for (const Mixture& m : r.mixtures) std::cout << "  " << MeasurementIdentity::describe(m) << "\n";
}

// What each shard lacks, and the command that completes it: in a Slurm merge job's log, the lines to act on.
void printGaps(const MergeReport& r) {
    if (r.incomplete.empty()) return;
    std::cout << "incomplete: " << r.incomplete << "\n";
    bool unknown = false;
    for (const ShardGap& g : r.gaps) {
        std::cout << "  " << (g.shard ? "shard " + shardName(r, g.shard) : std::string("shard not known"));
        if (g.missingCount) std::cout << ": missing " << ShardGaps::rangesText(g.missing);
        if (g.failedCount)
            std::cout << (g.missingCount ? "; " : ": ") << "failed " << ShardGaps::rangesText(g.failed);
        if (g.shard == 0)
            std::cout << " (the rows present do not tell which shard runs them)";
        else if (!g.partFileIsInput)
            std::cout << " (no input holds this shard's rows)";
        std::cout << "\n";
        unknown = unknown || g.shard == 0;
    }
    std::cout << "to complete the sweep, rerun these shards, then merge again (DEF: the definition of sweep "
              << r.sweepId << (r.sweepName.empty() ? "" : " '" + r.sweepName + "'")
              << " with the options its shards ran with; rows already there are kept):\n";
    for (const ShardGap& g : r.gaps)
        if (g.shard)
            std::cout << "  bench sweep DEF --shard " << shardName(r, g.shard) << " --csv "
                      << (g.partFile.empty() ? "PART" : shellWord(g.partFile))
                      << " --resume --retry-failed\n";
    if (unknown)
        std::cout << "  bench sweep DEF --shard i/" << r.shardCount
                  << " --csv PART --resume --retry-failed    for every shard i\n";
}

} // namespace

int MergeCommand::main(int argc, char** argv) {
    CLI::App app{"bench merge: join the CSVs of the shards of one sweep", "bench merge"};
    app.footer(R"(Examples:
  bench merge -o all.csv part1.csv part2.csv
  parallel bench sweep s.json --shard {}/4 --csv part{}.csv ::: 1 2 3 4 && bench merge -o all.csv part?.csv
  bench merge -o all.csv --allow-incomplete part*.csv    write what is there; the gaps are still listed
  bench merge -o all.csv --allow-mixed part*.csv         shards of two machine types, each mixture listed

Checks that every input comes from the same sweep definition (sweep_id), that no configuration is
in two inputs, and that the rows are one measurement: one commit (git_commit), CPU model (cpu_model),
driver (driver) and, per api, renderer and driver_version, and one GPU-timer verdict (shards calibrate
on their own). Hosts may differ (the nodes of a cluster) and are counted. Rows come out sorted by
config_index.

Missing configurations (no input holds them) and failed rows are listed per shard of the split
(shard i of N runs the groups g with g mod N = i - 1), each with the command that completes it:
  bench sweep DEF --shard i/N --csv PART --resume --retry-failed

Exit codes: 0 merged and complete; 1 configurations missing or failed (nothing written unless
--allow-incomplete, then 0) or an I/O failure; 2 the inputs do not fit together (another sweep or split,
a configuration twice, a mixture without --allow-mixed).)");
    std::vector<std::string> inputs;
    std::string output;
    MergeOptions options;
    app.add_option("inputs", inputs, "shard CSVs written by bench sweep --shard i/N")->required();
    app.add_option("-o,--output", output, "the merged CSV (written atomically)")->required();
    app.add_flag("--allow-incomplete", options.allowIncomplete,
                 "write even when configurations are missing or failed (still listed, exit 0)");
    app.add_flag("--force", options.force, "replace an existing output file");
    app.add_flag("--allow-mixed", options.allowMixed,
                 "write even when rows differ in commit, CPU model, renderer, driver or timer verdict "
                 "(each mixture listed)");
    app.add_flag("--allow-mixed-timer", options.allowMixedTimer,
                 "write even when rows carry different timer verdicts (reported, per verdict)");
    if (int code = parseCli(app, argc, argv, "bench merge"); code >= 0) return code;
    const MergeReport r = CsvMerge::merge(inputs, output, options);
    printSummary(r, output);
    printMixtures(r);
    printGaps(r);
    if (r.written) return 0;
    std::cout.flush(); // the report first, then the one line that says why it ends with exit 1
    std::cerr << "bench: error: incomplete: " << r.incomplete
              << "; nothing written: rerun the shards listed above, or pass --allow-incomplete\n";
    return int(ExitCode::Failure);
}

} // namespace sb
