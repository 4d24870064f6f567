#include "bench/lib/output/CsvWriter.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <unordered_map>

#include "bench/lib/output/AtomicFile.h"
#include "bench/lib/output/CsvReader.h"
#include "core/Error.h"

namespace sb {

namespace {

constexpr char kSeparator = ',';
constexpr char kQuote = '"';
constexpr const char* kNeedsQuoting = ",\"\r\n";
constexpr const char* kUtf8Bom = "\xEF\xBB\xBF";

[[noreturn]] void failWrite(const std::string& path, const std::string& what, int err) {
    throw Error("cannot write CSV '" + path + "': " + what +
                    (err ? std::string(": ") + std::strerror(err) : ""),
                ExitCode::Failure);
}

/// Column name -> index, so that merging a header of 100000 columns stays linear.
using ColumnIndex = std::unordered_map<std::string, size_t>;

ColumnIndex indexOf(const std::vector<std::string>& header) {
    ColumnIndex index;
    index.reserve(header.size());
    for (size_t i = 0; i < header.size(); ++i) index.emplace(header[i], i);
    return index;
}

// Header union in first-seen order: old columns keep their place, new ones follow in the order the new
// rows name them.
void widenHeader(std::vector<std::string>& header, ColumnIndex& index, const std::vector<CsvRow>& rows) {
    for (const CsvRow& row : rows)
        for (const auto& cell : row)
            if (index.emplace(cell.first, header.size()).second) header.push_back(cell.first);
}

// New rows leave the columns they do not name empty.
std::vector<std::string> cellsOf(const CsvRow& row, const ColumnIndex& index, size_t width,
                                 const std::string& path) {
    std::vector<std::string> cells(width);
    std::vector<bool> seen(width, false);
    for (const auto& [column, value] : row) {
        size_t i = index.at(column);
        // Two values for one column would silently drop one measurement: a bug in the caller.
        if (seen[i]) failWrite(path, "a new row names column '" + column + "' twice", 0);
        seen[i] = true;
        cells[i] = value;
    }
    return cells;
}

void mergeRows(CsvTable& table, const std::vector<CsvRow>& rows, const std::string& path) {
    ColumnIndex index = indexOf(table.header);
    widenHeader(table.header, index, rows);
    for (auto& old : table.rows) old.resize(table.header.size());
    for (const CsvRow& row : rows) table.rows.push_back(cellsOf(row, index, table.header.size(), path));
}

void appendLine(std::string& out, const std::vector<std::string>& cells) {
    // A record that is one empty cell would otherwise be a blank line, which readers skip.
    if (cells.size() == 1 && cells[0].empty()) {
        out += "\"\"\n";
        return;
    }
    for (size_t i = 0; i < cells.size(); ++i) {
        if (i) out += kSeparator;
        out += CsvWriter::quote(cells[i]);
    }
    out += '\n'; // LF rather than RFC 4180's CRLF: the files live in git and are read by Python/R
}

// In place only when every new row fits the header as it is and is one physical line: then a writer
// killed half-way leaves a partial last line that the next writer can cut at the last newline without
// cutting into a complete row.
bool fitsInPlace(const std::vector<CsvRow>& rows, const ColumnIndex& index) {
    for (const CsvRow& row : rows)
        for (const auto& [column, value] : row)
            if (!index.count(column) || value.find_first_of("\r\n") != std::string::npos) return false;
    return true;
}

// The rewrite, streamed: the old rows go through one at a time (less those `drop` accepts, when given),
// widened with empty cells for the new columns (which come last), then the new rows.
void rewriteWidened(AtomicFile& file, CsvReader& reader, std::vector<std::string> header,
                    const std::vector<CsvRow>& rows, const std::string& path,
                    const CsvWriter::RowFilter* drop = nullptr) {
    const std::vector<std::string> oldHeader = drop ? header : std::vector<std::string>();
    const size_t oldWidth = header.size();
    ColumnIndex index = indexOf(header);
    widenHeader(header, index, rows);
    file.beginReplace();
    std::string text;
    appendLine(text, header);
    std::vector<std::string> record;
    while (reader.next(record)) {
        if (record.size() != oldWidth)
            reader.fail(reader.line(), "row has " + std::to_string(record.size()) +
                                           " fields but the header has " + std::to_string(oldWidth));
        if (drop && (*drop)(oldHeader, record)) continue;
        record.resize(header.size());
        appendLine(text, record);
        file.write(text);
        text.clear();
    }
    for (const CsvRow& row : rows) appendLine(text, cellsOf(row, index, header.size(), path));
    file.write(text);
    file.commit();
}

/// A partial last line (a writer killed while appending it) is cut before anything is added after it.
void cutPartialLine(AtomicFile& file, const std::string& path) {
    if (off_t cut = file.cutPartialLastLine())
        std::cerr << "bench: warning: " << path << ": cut a partial last line of " << cut
                  << " bytes (left by a writer killed while appending it)\n";
}

} // namespace

std::string CsvWriter::serialize(const CsvTable& table) {
    std::string out;
    appendLine(out, table.header);
    for (const auto& row : table.rows) appendLine(out, row);
    return out;
}

CsvTable CsvWriter::toTable(const std::vector<CsvRow>& rows) {
    CsvTable table;
    mergeRows(table, rows, "(rows)");
    return table;
}

void CsvWriter::writeText(const std::string& path, const std::string& text) {
    AtomicFile file(path, "file");
    file.replace(text);
}

std::string CsvWriter::quote(const std::string& field) {
    // A field that begins with a byte-order mark is quoted too: unquoted at the start of a file, the
    // reader would take it for the file's BOM and strip it, renaming the column.
    const bool startsWithBom = field.compare(0, 3, kUtf8Bom) == 0;
    if (!startsWithBom && field.find_first_of(kNeedsQuoting) == std::string::npos) return field;
    std::string out(1, kQuote);
    for (char c : field) {
        if (c == kQuote) out += kQuote;
        out += c;
    }
    return out + kQuote;
}

// Everything happens under the file's lock (bench/lib/output/AtomicFile.h), so two processes appending
// to one file both keep their rows. Only the header is read when the rows fit it: the append is then
// one write at the end of the file, whatever its size; a new column needs the (streamed) rewrite.
void CsvWriter::appendRows(const std::string& path, const std::vector<CsvRow>& rows) {
    if (rows.empty()) return; // nothing to add, and no header to create a new file with
    AtomicFile file(path, "CSV");
    cutPartialLine(file, path);
    CsvReader reader(file.fd(), path);
    // A corrupt header is an error (BadInput, naming file and line), never silently replaced.
    std::vector<std::string> header = reader.header();
    const ColumnIndex index = indexOf(header);
    if (header.empty() || !fitsInPlace(rows, index))
        return rewriteWidened(file, reader, std::move(header), rows, path);
    std::string text;
    for (const CsvRow& row : rows) appendLine(text, cellsOf(row, index, header.size(), path));
    file.appendInPlace(text);
}

// Always the rewrite: rows leave the file, which no append in place can do.
void CsvWriter::replaceRows(const std::string& path, const RowFilter& drop, const std::vector<CsvRow>& rows) {
    if (rows.empty()) return; // nothing replaces the dropped rows: never a removal alone
    AtomicFile file(path, "CSV");
    cutPartialLine(file, path);
    CsvReader reader(file.fd(), path);
    std::vector<std::string> header = reader.header();
    rewriteWidened(file, reader, std::move(header), rows, path, &drop);
}

// A ragged table would be written without complaint but could not be read back, so it is refused
// before anything touches the disk.
void CsvWriter::writeTable(const std::string& path, const CsvTable& table) {
    for (size_t i = 0; i < table.rows.size(); ++i)
        if (table.rows[i].size() != table.header.size())
            failWrite(path,
                      "row " + std::to_string(i + 1) + " has " + std::to_string(table.rows[i].size()) +
                          " cells but the header has " + std::to_string(table.header.size()),
                      0);
    writeText(path, serialize(table));
}

void CsvWriter::checkWritable(const std::string& path) {
    AtomicFile::checkWritable(path, "CSV");
}

CsvTable CsvWriter::read(const std::string& path) {
    return read(path, [](const std::string&) { return true; });
}

CsvTable CsvWriter::read(const std::string& path, const std::function<bool(const std::string&)>& keep) {
    CsvReader reader(path);
    return readTable(reader, keep);
}

CsvTable CsvWriter::parse(const std::string& text, const std::string& sourceName) {
    CsvReader reader(std::string_view(text), sourceName);
    return readTable(reader, [](const std::string&) { return true; });
}

CsvTable CsvWriter::readTable(CsvReader& reader, const std::function<bool(const std::string&)>& keep) {
    CsvTable table;
    const std::vector<std::string> header = reader.header();
    std::vector<size_t> kept;
    for (size_t i = 0; i < header.size(); ++i)
        if (keep(header[i])) {
            kept.push_back(i);
            table.header.push_back(header[i]);
        }
    // A header none of whose columns is wanted keeps its first: the table still reads as a table of
    // other columns (compare then says it is no result table), not as an empty file.
    if (kept.empty() && !header.empty()) {
        kept.push_back(0);
        table.header.push_back(header[0]);
    }
    std::vector<std::string> record;
    while (reader.next(record)) {
        if (record.size() != header.size())
            reader.fail(reader.line(), "row has " + std::to_string(record.size()) +
                                           " fields but the header has " + std::to_string(header.size()));
        std::vector<std::string> row;
        row.reserve(kept.size());
        for (size_t i : kept) row.push_back(std::move(record[i]));
        table.rows.push_back(std::move(row));
    }
    return table;
}

std::string CsvWriter::line(const std::vector<std::string>& cells) {
    std::string out;
    appendLine(out, cells);
    return out;
}

} // namespace sb
