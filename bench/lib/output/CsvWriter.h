#pragma once
// Result CSV files (docs/ARCHITECTURE.md, "Results"): one row per measured configuration, header of column
// names. Appending is safe against concurrent writers and loses nothing: under the file's lock
// (bench/lib/output/AtomicFile.h) only the header is read. When every new row's columns are in it and no
// cell holds a line break, the rows are appended in place (one write at the end, fsync; cells of the
// header's other columns empty): a crash then leaves the old rows whole plus at most a partial last line,
// which the next append cuts and readers skip with a warning (bench/lib/output/CsvReader.h). Rows with new
// columns widen the header (the union of old and new columns, in first-seen order; cells of missing columns
// stay empty) and the file is rewritten, streamed row by row, through a temp file, fsync and rename: a crash
// then leaves either the old or the new file. Two processes appending to one file both keep their rows.
// Quoting follows RFC 4180 (fields with , " CR LF are quoted, quotes doubled).
#include <algorithm>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace sb {

class CsvReader;

/// One row: ordered (column, value) pairs. Order is the column order for a new file.
using CsvRow = std::vector<std::pair<std::string, std::string>>;

struct CsvTable {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows; ///< each row has header.size() cells

    bool hasColumn(const std::string& column) const {
        return std::find(header.begin(), header.end(), column) != header.end();
    }
    /// The cell of `row` in `column`, "" when the table has no such column.
    std::string cell(const std::vector<std::string>& row, const std::string& column) const {
        auto it = std::find(header.begin(), header.end(), column);
        return it == header.end() ? "" : row[size_t(it - header.begin())];
    }
};

class CsvWriter {
public:
    /// Appends rows to `path` (creating it). Throws sb::Error(ExitCode::Failure) naming the path and
    /// the OS error when the directory is missing or unwritable, BadInput when the path is empty or names
    /// a device, FIFO, socket or directory; the original file is then untouched.
    static void appendRows(const std::string& path, const std::vector<CsvRow>& rows);
    /// Which existing rows replaceRows removes: called with the file's header and one row's cells.
    using RowFilter =
        std::function<bool(const std::vector<std::string>& header, const std::vector<std::string>& cells)>;
    /// Appends `rows` as appendRows does and, in the same rewrite under the same lock, removes the rows
    /// already in the file that `drop` accepts: the file is streamed through the temp file, fsync and
    /// rename, so a reader or a crash sees either the old rows or the new ones, never both and never
    /// neither (a sweep's failed row and the row of its retry). Throws like appendRows.
    static void replaceRows(const std::string& path, const RowFilter& drop, const std::vector<CsvRow>& rows);
    /// Checks up front that `path` can be written (a regular file or nothing, directory exists and is
    /// writable), so a bad --csv fails before minutes of measuring. Throws sb::Error(BadInput).
    static void checkWritable(const std::string& path);
    /// Parses a CSV file written by appendRows (RFC 4180). Throws on a missing file, a device or ragged
    /// rows (a FIFO is read to its end).
    static CsvTable read(const std::string& path);
    /// The same keeping only the columns `keep` accepts (compare needs a few of many columns); a header
    /// none of whose columns it accepts keeps its first, so the file never reads as empty.
    static CsvTable read(const std::string& path, const std::function<bool(const std::string&)>& keep);
    /// The rest of `reader` as a table (header first), keeping the columns `keep` accepts.
    static CsvTable readTable(CsvReader& reader, const std::function<bool(const std::string&)>& keep);
    static CsvTable parse(const std::string& text, const std::string& sourceName);
    /// Writes `table` to `path`, replacing any existing file atomically under the same lock and with the
    /// same temp file, fsync, rename and directory fsync steps as appendRows (it keeps its mode). Every row
    /// must have header.size() cells. Throws like appendRows; on failure no temp file is left and the old
    /// file, if any, is untouched.
    static void writeTable(const std::string& path, const CsvTable& table);
    /// The exact text appendRows writes for `table`: header line, then one line per row, RFC 4180
    /// quoting, LF line ends.
    static std::string serialize(const CsvTable& table);
    /// Rows as a table: the header is the union of their columns in first-seen order, missing cells
    /// empty (the same merge appendRows does into an existing file).
    static CsvTable toTable(const std::vector<CsvRow>& rows);
    /// Replaces `path` with `text` atomically and under the lock (temp file, fsync, rename, directory
    /// fsync): for the other formats of the same rows (bench export -o). Throws like appendRows.
    static void writeText(const std::string& path, const std::string& text);
    static std::string quote(const std::string& field);
    /// One record as serialize writes it, with its LF.
    static std::string line(const std::vector<std::string>& cells);
};

} // namespace sb
