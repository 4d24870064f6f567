#include "bench/lib/output/RowExport.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "bench/lib/output/DashboardExport.h"
#include "bench/lib/output/ResultColumns.h"
#include "core/Error.h"

namespace sb {

namespace {

using OrderedJson = nlohmann::ordered_json;

constexpr int kJsonIndent = 2;
constexpr const char* kNoRows = "(no rows)\n";
constexpr size_t kMinSeparatorWidth = 3; // "---" is the shortest delimiter GFM accepts

// The one table of row formats. Order is the order of --help.
constexpr RowFormatEntry kFormatEntries[] = {
    {RowFormat::Console, "console", "tables", false},
    {RowFormat::Csv, "csv", "", true},
    {RowFormat::Json, "json", "", true},
    {RowFormat::Markdown, "md", "", true},
    {RowFormat::Markdown, "markdown", "", true},
    {RowFormat::GoogleBenchmark, "gbench", "Google Benchmark JSON", true},
    {RowFormat::GithubBenchmark, "gh-benchmark", "github-action-benchmark", true},
};
constexpr NameTable kFormats{kFormatEntries};

const std::vector<std::string> kIdentifierColumns = {col::kGitCommit, col::kSceneHash, col::kSweepId,
                                                     col::kSeed,      col::kShard,     "config_key"};
const std::vector<std::string> kIdentifierSuffixes = {"_hash", "_id"};

bool isDigit(char c) {
    return c >= '0' && c <= '9';
}

bool endsWith(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The JSON number grammar, checked by hand because from_chars (and strtod) also take "inf", "nan",
// leading zeros, ".5" and "1.". Staying inside the grammar means a value a spreadsheet would show
// with leading zeros (a padded index, a commit-like "0123") is never silently turned into 123.
bool isJsonNumberLiteralText(const std::string& s) {
    size_t i = 0;
    const size_t n = s.size();
    auto skipDigits = [&] {
        size_t start = i;
        while (i < n && isDigit(s[i])) ++i;
        return i > start;
    };
    if (i < n && s[i] == '-') ++i;
    if (i >= n || !isDigit(s[i])) return false;
    if (s[i] == '0')
        ++i;
    else
        skipDigits();
    if (i < n && s[i] == '.' && (++i, !skipDigits())) return false;
    if (i < n && (s[i] == 'e' || s[i] == 'E')) {
        ++i;
        if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
        if (!skipDigits()) return false;
    }
    return i == n;
}

// from_chars rather than strtod: it does not depend on the C locale's decimal point.
std::optional<double> parseDouble(const std::string& s) {
    double v = 0.0;
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

// Integers keep their exact value (a counter of 2^60 must not become 1.152921504606847e18); only
// those beyond 64 bits fall back to double.
OrderedJson numberValue(const std::string& s) {
    const char* first = s.data();
    const char* last = s.data() + s.size();
    if (s.find_first_of(".eE") == std::string::npos) {
        int64_t i = 0;
        if (auto r = std::from_chars(first, last, i); r.ec == std::errc() && r.ptr == last) return i;
        uint64_t u = 0;
        if (auto r = std::from_chars(first, last, u); r.ec == std::errc() && r.ptr == last) return u;
    }
    return *parseDouble(s); // isNumber() said it parses
}

/// Per column: true when its cells become JSON numbers (and Markdown right-aligns it).
std::vector<bool> numericColumns(const CsvSource& source) {
    const std::vector<std::string>& header = source.header();
    std::vector<bool> numeric(header.size());
    for (size_t c = 0; c < header.size(); ++c) numeric[c] = !RowExport::isIdentifierColumn(header[c]);
    source.forEachRow([&](const std::vector<std::string>& row, size_t) {
        for (size_t c = 0; c < row.size(); ++c)
            if (numeric[c] && !row[c].empty() && !RowExport::isNumber(row[c])) numeric[c] = false;
    });
    return numeric;
}

std::vector<bool> numericColumns(const CsvTable& table) {
    return numericColumns(CsvSource::table(table));
}

// Invalid UTF-8 in a cell (a renderer string from a broken driver) is replaced, not fatal.
std::string dumpJson(const OrderedJson& value, int indent = -1) {
    return value.dump(indent, ' ', false, OrderedJson::error_handler_t::replace);
}

// ---------------------------------------------------------------------------------------------------
// Markdown

std::string escapeMarkdown(const std::string& cell) {
    std::string out;
    for (size_t i = 0; i < cell.size(); ++i) {
        char c = cell[i];
        if (c == '|')
            out += "\\|";
        else if (c == '\r' && i + 1 < cell.size() && cell[i + 1] == '\n')
            continue; // CRLF: one space
        else if (c == '\r' || c == '\n')
            out += ' ';
        else
            out += c;
    }
    return out;
}

// Padding counts code points so that names like "µs" do not push a column out of line in a terminal.
size_t displayWidth(const std::string& s) {
    return size_t(std::count_if(s.begin(), s.end(), [](char c) { return (uint8_t(c) & 0xC0) != 0x80; }));
}

std::string pad(const std::string& s, size_t width, bool right) {
    std::string fill(width - std::min(width, displayWidth(s)), ' ');
    return right ? fill + s : s + fill;
}

struct MarkdownColumn {
    size_t index; ///< into the table's header and rows
    bool numeric;
};

struct MarkdownLayout {
    std::vector<MarkdownColumn> common;  ///< same value in every row
    std::vector<MarkdownColumn> varying; ///< the table's columns
};

// Splits the considered columns into the common list and the table; empty columns go nowhere.
MarkdownLayout layoutColumns(const CsvTable& table, bool allColumns) {
    std::vector<bool> numeric = numericColumns(table);
    MarkdownLayout layout;
    auto consider = [&](size_t c) {
        const auto& rows = table.rows;
        bool allEmpty = std::all_of(rows.begin(), rows.end(), [c](const auto& r) { return r[c].empty(); });
        if (allEmpty) return;
        bool constant =
            std::all_of(rows.begin(), rows.end(), [&](const auto& r) { return r[c] == rows[0][c]; });
        // With one row every column is "constant"; a table still reads better than a list of everything.
        (constant && rows.size() > 1 ? layout.common : layout.varying).push_back({c, numeric[c]});
    };
    if (allColumns) {
        for (size_t c = 0; c < table.header.size(); ++c) consider(c);
    } else {
        for (const std::string& name : RowExport::markdownColumns()) {
            auto it = std::find(table.header.begin(), table.header.end(), name);
            if (it != table.header.end()) consider(size_t(it - table.header.begin()));
        }
    }
    return layout;
}

std::string commonList(const CsvTable& table, const std::vector<MarkdownColumn>& common) {
    std::string out = "Common to all " + std::to_string(table.rows.size()) + " rows:\n";
    for (const MarkdownColumn& col : common)
        out += "- " + escapeMarkdown(table.header[col.index]) + ": " +
               escapeMarkdown(table.rows[0][col.index]) + "\n";
    return out;
}

std::string tableLine(const std::vector<std::string>& cells) {
    std::string out = "|";
    for (const std::string& cell : cells) out += " " + cell + " |";
    return out + "\n";
}

std::string markdownTable(const CsvTable& table, const std::vector<MarkdownColumn>& columns) {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> body(table.rows.size());
    for (const MarkdownColumn& col : columns) {
        header.push_back(escapeMarkdown(table.header[col.index]));
        for (size_t r = 0; r < table.rows.size(); ++r)
            body[r].push_back(escapeMarkdown(table.rows[r][col.index]));
    }
    std::vector<std::string> separator;
    for (size_t c = 0; c < columns.size(); ++c) {
        size_t width = std::max(kMinSeparatorWidth, displayWidth(header[c]));
        for (const auto& row : body) width = std::max(width, displayWidth(row[c]));
        bool right = columns[c].numeric;
        header[c] = pad(header[c], width, false);
        for (auto& row : body) row[c] = pad(row[c], width, right);
        separator.push_back(right ? std::string(width - 1, '-') + ":" : std::string(width, '-'));
    }
    std::string out = tableLine(header) + tableLine(separator);
    for (const auto& row : body) out += tableLine(row);
    return out;
}

} // namespace

const NameTable<RowFormatEntry>& rowFormats() {
    return kFormats;
}

RowFormat parseRowFormat(const std::string& name) {
    if (std::optional<RowFormat> f = kFormats.parse(name)) return *f;
    throw Error("unknown output format '" + name + "' (valid: " + kFormats.list() + ")", ExitCode::BadInput);
}

std::string rowFormatChoices(bool textOnly) {
    return kFormats.labelledChoices([&](const RowFormatEntry& e) -> std::optional<std::string> {
        if (textOnly && !e.text) return std::nullopt;
        return std::string(e.name) + (*e.note ? std::string(" (") + e.note + ")" : "");
    });
}

std::string RowExport::format(const CsvTable& table, RowFormat format) {
    switch (format) {
    case RowFormat::Csv:
        return toCsv(table);
    case RowFormat::Json:
        return toJson(table);
    case RowFormat::Markdown:
        return toMarkdown(table);
    case RowFormat::GoogleBenchmark:
        return DashboardExport::googleBenchmark(table);
    case RowFormat::GithubBenchmark:
        return DashboardExport::githubActionBenchmark(table);
    case RowFormat::Console:
        break;
    }
    throw std::invalid_argument("RowExport::format: the console format is printed by ConsoleReport");
}

std::string RowExport::toCsv(const CsvTable& table) {
    return CsvWriter::serialize(table);
}

bool RowExport::isIdentifierColumn(const std::string& column) {
    if (std::find(kIdentifierColumns.begin(), kIdentifierColumns.end(), column) != kIdentifierColumns.end())
        return true;
    return std::any_of(kIdentifierSuffixes.begin(), kIdentifierSuffixes.end(),
                       [&](const std::string& suffix) { return endsWith(column, suffix); });
}

bool RowExport::isJsonNumberLiteral(const std::string& cell) {
    return isJsonNumberLiteralText(cell);
}

bool RowExport::isNumber(const std::string& cell) {
    return isJsonNumberLiteralText(cell) && parseDouble(cell).has_value();
}

// Typing is per column, not per cell: a column that is numeric in one row and text in another would
// make every consumer check the type of each value.
std::string RowExport::toJson(const CsvTable& table) {
    std::string out;
    writeJson(CsvSource::table(table), [&](std::string_view text) { out += text; });
    return out;
}

// The text nlohmann's dump(2) gives for {"columns": [...], "rows": [...]}, written a row at a time: each
// row object is dumped on its own and indented to its place.
void RowExport::writeJson(const CsvSource& source, const TextSink& sink) {
    const std::vector<std::string>& header = source.header();
    const std::vector<bool> numeric = numericColumns(source);
    std::vector<std::string> keys;
    for (const std::string& name : header) keys.push_back(dumpJson(OrderedJson(name)));
    std::string text = "{\n  \"columns\": [";
    for (size_t c = 0; c < keys.size(); ++c) text += (c ? ",\n    " : "\n    ") + keys[c];
    text += keys.empty() ? "],\n  \"rows\": [" : "\n  ],\n  \"rows\": [";
    sink(text);
    bool first = true;
    source.forEachRow([&](const std::vector<std::string>& row, size_t) {
        std::string out = first ? "\n    {" : ",\n    {";
        for (size_t c = 0; c < header.size(); ++c) {
            const std::string& cell = row[c];
            out += (c ? ",\n      " : "\n      ") + keys[c] + ": " +
                   (cell.empty() ? std::string("null")
                    : numeric[c] ? dumpJson(numberValue(cell))
                                 : dumpJson(OrderedJson(cell)));
        }
        out += header.empty() ? "}" : "\n    }";
        first = false;
        sink(out);
    });
    sink(first ? "]\n}\n" : "\n  ]\n}\n");
}

void RowExport::write(const CsvSource& source, RowFormat format, const TextSink& sink) {
    switch (format) {
    case RowFormat::Csv:
        sink(CsvWriter::line(source.header()));
        source.forEachRow([&](const std::vector<std::string>& row, size_t) { sink(CsvWriter::line(row)); });
        return;
    case RowFormat::Json:
        return writeJson(source, sink);
    case RowFormat::GoogleBenchmark:
        return DashboardExport::writeGoogleBenchmark(source, sink);
    case RowFormat::GithubBenchmark:
        return DashboardExport::writeGithubActionBenchmark(source, sink);
    case RowFormat::Markdown:
    case RowFormat::Console:
        break;
    }
    throw std::invalid_argument("RowExport::write: Markdown and the console are not streamed");
}

std::string RowExport::toMarkdown(const CsvTable& table, bool allColumns) {
    if (table.rows.empty()) return kNoRows;
    MarkdownLayout layout = layoutColumns(table, allColumns);
    std::string out;
    if (!layout.common.empty()) out += commonList(table, layout.common);
    if (!layout.common.empty() && !layout.varying.empty()) out += "\n";
    if (!layout.varying.empty()) out += markdownTable(table, layout.varying);
    // Say so rather than print nothing, which reads like a crash.
    if (out.empty()) out = "(" + std::to_string(table.rows.size()) + " rows, no column to show)\n";
    return out;
}

// What a reader compares first: the outcome, the configuration, then timings, accuracy and load.
// One line per group reads better than clang-format's one name per line.
const std::vector<std::string>& RowExport::markdownColumns() {
    // clang-format off
    static const std::vector<std::string> kColumns = {
        col::kStatus, col::kError,
        col::kTechnique, col::kProperties, col::kScene, col::kInstances, col::kScale, col::kTessellation, col::kSubmit, col::kCamera,
        col::kWidth, col::kHeight, col::kLights, col::kPerturbation, col::kRepeat, col::kFrames,
        col::kWallMsMedian, col::kWallMsP5, col::kWallMsP95, col::kWallMsMad, col::kCpuSubmitMsMedian, col::kFpsMedian,
        col::kGpuMsMedian, col::kWallRatioVsBaseline, col::kTimerVerdict,
        col::kAccWrongPct, col::kAccWrongNoEdgePct, col::kAccRmse, col::kAccNan, col::kAccInf, col::kAccOutOfRange,
        col::kAccGainCamera, col::kAccGainLight, col::kAccFlicker,
        col::kLoadGlCalls, col::kLoadVertices, col::kLoadFragments,
        col::kRenderer,
    };
    // clang-format on
    return kColumns;
}

} // namespace sb
