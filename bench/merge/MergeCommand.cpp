#include "bench/merge/MergeCommand.h"

#include <iostream>

#include "bench/lib/options/CliParse.h"
#include "bench/lib/output/CsvMerge.h"

namespace sb {

int MergeCommand::main(int argc, char** argv) {
    CLI::App app{"bench merge: join the CSVs of the shards of one sweep", "bench merge"};
    app.footer(R"(Examples:
  bench merge -o all.csv part1.csv part2.csv
  parallel bench sweep s.json --shard {}/4 --csv part{}.csv ::: 1 2 3 4 && bench merge -o all.csv part?.csv

Checks that every input comes from the same sweep definition (sweep_id), that no configuration is
in two inputs and none is missing, and that every measured row carries the same GPU-timer verdict
(shards calibrate on their own: a trusted shard beside an untrusted one ran on different devices or
drivers); rows come out sorted by config_index.)");
    std::vector<std::string> inputs;
    std::string output;
    MergeOptions options;
    app.add_option("inputs", inputs, "shard CSVs written by bench sweep --shard i/N")->required();
    app.add_option("-o,--output", output, "the merged CSV (written atomically)")->required();
    app.add_flag("--allow-incomplete", options.allowIncomplete, "write even when configurations are missing");
    app.add_flag("--force", options.force, "replace an existing output file");
    app.add_flag("--allow-mixed-timer", options.allowMixedTimer,
                 "write even when rows carry different timer verdicts (reported, per verdict)");
    if (int code = parseCli(app, argc, argv, "bench merge"); code >= 0) return code;
    const MergeReport r = CsvMerge::merge(inputs, output, options);
    std::cout << "merged " << r.files << " files of sweep " << r.sweepId << ": " << r.rows << " rows of "
              << r.configs << " configurations";
    if (r.failedRows) std::cout << " (" << r.failedRows << " failed)";
    if (r.missingCount) std::cout << ", " << r.missingCount << " missing";
    std::cout << " -> " << output << "\n";
    if (r.timerVerdicts.size() > 1) {
        std::cout << "warning: rows carry different GPU-timer verdicts:";
        for (const auto& [verdict, rows] : r.timerVerdicts) std::cout << " " << verdict << " " << rows;
        std::cout << " (compare GPU columns only within one verdict)\n";
    }
    return 0;
}

} // namespace sb
