#pragma once
// Result rows (a CsvTable as CsvWriter reads it) in the formats other tools and people want: the CSV
// text itself, JSON for scripts, a Markdown table for issues and reports. The console table is
// ConsoleReport's business; RowFormat::Console only names it for the command line.
#include <string>
#include <vector>

#include "bench/lib/output/CsvSource.h"
#include "bench/lib/output/CsvWriter.h"
#include "core/NameTable.h"

namespace sb {

enum class RowFormat { Console, Csv, Json, Markdown, GoogleBenchmark, GithubBenchmark };

/// One row of the format table (RowExport.cpp): adding a format is one value above, one row and its
/// writer in RowExport::format; --format's help and errors everywhere come from the table.
struct RowFormatEntry {
    RowFormat value;
    const char* name; ///< --format value; a second row with the same value is an accepted alias
    const char* note; ///< shown after the name in help ("tables"), or ""
    bool text;        ///< a text export of the rows (`bench export` writes only these)
};
const NameTable<RowFormatEntry>& rowFormats();
/// "console", "csv", "json", "md" (also "markdown"), "gbench", "gh-benchmark" (bench/lib/output/
/// DashboardExport.h); exact, lower case. Throws sb::Error(BadInput)
/// naming the bad value and listing the valid names.
RowFormat parseRowFormat(const std::string& name);
/// --format's help: "console (tables), csv, json or md"; `textOnly`: "csv, json or md".
std::string rowFormatChoices(bool textOnly = false);

class RowExport {
public:
    /// toCsv, toJson, toMarkdown (curated columns) or a dashboard format (DashboardExport) by format.
    /// RowFormat::Console is not a text export (ConsoleReport prints it); asking for it throws
    /// std::invalid_argument, a caller's bug.
    static std::string format(const CsvTable& table, RowFormat format);
    /// The same streamed: csv, json and the dashboard formats go to `sink` a row at a time, reading
    /// `source` once or twice and holding one row (Markdown needs every row for its column widths and
    /// is built in memory). The text is the same as format()'s.
    static void write(const CsvSource& source, RowFormat format, const TextSink& sink);

    /// RFC 4180 text exactly as CsvWriter writes files (header line + rows, LF line ends); it is
    /// CsvWriter::serialize.
    static std::string toCsv(const CsvTable& table);

    /// {"columns": [...], "rows": [{"col": value, ...}, ...]}, 2-space indent, ending in a newline.
    /// Every row object lists all columns in header order. Cells are typed per column:
    /// - empty cell: null;
    /// - a column whose every non-empty cell is a JSON number literal (optional '-', then "0" or a digit
    ///   string without leading zero, optional ".digits", optional exponent "e"/"E" [+-] digits) with a
    ///   finite value: numbers. So "12", "-0.5", "1.2500", "1e5" are numbers; "0123", "+1", "0x1A",
    ///   "inf", "nan", ".5", "1.", " 1", "1e999", "1e-999" (out of double range) are not. Integers stay
    ///   integers (64 bit; a larger one becomes a double); "1.2500" is written as 1.25, "1e5" as 100000.0;
    /// - identifier columns (see isIdentifierColumn) and every other column: strings.
    static std::string toJson(const CsvTable& table);
    /// toJson streamed: one pass types the columns, the next writes the rows one at a time.
    static void writeJson(const CsvSource& source, const TextSink& sink);

    /// A GitHub-flavoured Markdown table for people. The columns considered are markdownColumns() that
    /// the table has, in that order, or with allColumns every column of the table in header order.
    /// With two or more rows, a considered column holding the same non-empty value in every row leaves
    /// the table for a list above it:
    ///
    ///     Common to all 2 rows:
    ///     - technique: shadowmap
    ///
    ///     | scene | wall_ms_median |
    ///     | ----- | -------------: |
    ///     | a     |         1.2000 |
    ///     | b     |        12.5000 |
    ///
    /// A column empty in every row is dropped. A single row is printed as a one-row table (no common
    /// list). When every remaining column is common, only the list is printed; when no column is left
    /// at all (all empty, or none of the curated ones present), the line "(N rows, no column to show)".
    /// Cells are the CSV text (numbers as in the CSV), '|' escaped as '\|', CR, LF and CRLF replaced by
    /// one space each, padded to the column width (in UTF-8 code points); columns typed as numbers by
    /// toJson's rule are right-aligned. The list escapes values the same way. A table without rows
    /// gives the single line "(no rows)". The output ends in a newline.
    static std::string toMarkdown(const CsvTable& table, bool allColumns = false);

    /// The curated key columns of toMarkdown, in order: status, error, technique, properties, scene,
    /// instances, scale, tessellation, submit, camera, width, height, lights, perturbation, repeat,
    /// frames, wall_ms_median, wall_ms_p5, wall_ms_p95, wall_ms_mad, cpu_submit_ms_median, fps_median,
    /// gpu_ms_median, wall_ratio_vs_baseline, timer_verdict, acc_wrong_pct, acc_wrong_no_edge_pct,
    /// acc_rmse, acc_nan, acc_inf, acc_out_of_range, acc_gain_camera, acc_gain_light, acc_flicker,
    /// load_gl_calls, load_vertices, load_fragments, renderer.
    static const std::vector<std::string>& markdownColumns();

    /// Columns whose values are names, never quantities, even when they look numeric: git_commit,
    /// scene_hash, sweep_id, seed, shard, config_key and any column ending in "_hash" or "_id".
    static bool isIdentifierColumn(const std::string& column);

    /// True when `cell` is a number by toJson's rule (JSON number literal with a finite value).
    static bool isNumber(const std::string& cell);
    /// True when `cell` follows the JSON number grammar (no "inf", "nan", leading zeros, ".5", "1.").
    static bool isJsonNumberLiteral(const std::string& cell);
};

} // namespace sb
