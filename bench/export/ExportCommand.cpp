#include "bench/export/ExportCommand.h"

#include <iostream>

#include "bench/lib/options/CliParse.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/output/RowExport.h"
#include "bench/lib/output/StandardStreams.h"
#include "core/Error.h"

namespace sb {

int ExportCommand::main(int argc, char** argv) {
    CLI::App app{"bench export: a result CSV as JSON, Markdown, CSV or a dashboard's JSON", "bench export"};
    app.footer(R"(Examples:
  bench export results.csv --format md                 key columns as a Markdown table on stdout
  bench export results.csv --format md --all-columns   every column
  bench export results.csv --format json -o results.json
  bench export results.csv --format gbench -o bench.json        Google Benchmark JSON (compare.py, Bencher)
  bench export ci-out/work.csv --format gh-benchmark -o gh.json  github-action-benchmark customSmallerIsBetter)");
    std::string input, output, format = "json";
    bool allColumns = false;
    app.add_option("input", input, "a CSV written by bench")->required();
    app.add_option("--format", format, rowFormatChoices(true))->capture_default_str();
    app.add_option("-o,--output", output, "write here (atomically) instead of stdout");
    app.add_flag("--all-columns", allColumns, "md: every column instead of the key ones");
    if (int code = parseCli(app, argc, argv, "bench export"); code >= 0) return code;
    const RowFormat f = parseRowFormat(format);
    if (!rowFormats().find(f)->text)
        throw Error("--format " + format + ": export writes " + rowFormatChoices(true));
    if (output.empty()) StandardStreams::requireStdout("bench export");
    const CsvTable table = CsvWriter::read(input);
    const std::string text =
        f == RowFormat::Markdown ? RowExport::toMarkdown(table, allColumns) : RowExport::format(table, f);
    if (output.empty()) {
        std::cout << text;
        StandardStreams::finishStdout("bench export");
    } else
        CsvWriter::writeText(output, text);
    return 0;
}

} // namespace sb
