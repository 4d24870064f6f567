#include "bench/export/ExportCommand.h"

#include <iostream>

#include "bench/lib/options/CliParse.h"
#include "bench/lib/output/AtomicFile.h"
#include "bench/lib/output/CsvSource.h"
#include "bench/lib/output/RowExport.h"
#include "bench/lib/output/StandardStreams.h"
#include "core/Error.h"

namespace sb {

namespace {

// Markdown needs every row for its column widths; the other formats are streamed.
void writeRows(const CsvSource& source, RowFormat format, bool allColumns, const TextSink& sink) {
    if (format != RowFormat::Markdown) return RowExport::write(source, format, sink);
    CsvTable table{source.header(), {}};
    source.forEachRow([&](const std::vector<std::string>& row, size_t) { table.rows.push_back(row); });
    sink(RowExport::toMarkdown(table, allColumns));
}

} // namespace

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
    const CsvSource source = CsvSource::file(input);
    if (output.empty()) {
        writeRows(source, f, allColumns, [](std::string_view text) { std::cout << text; });
        StandardStreams::finishStdout("bench export");
        return 0;
    }
    // Row by row into the temp file; a refusal half-way removes it and leaves the old output alone.
    AtomicFile file(output, "file");
    file.beginReplace();
    writeRows(source, f, allColumns, [&](std::string_view text) { file.write(text); });
    file.commit();
    return 0;
}

} // namespace sb
