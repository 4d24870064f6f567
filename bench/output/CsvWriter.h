#pragma once
// Result CSV files (docs/ARCHITECTURE.md, "Results"): one row per measured configuration, header of column
// names. Appending is atomic and loses nothing: the existing file is read, the new rows appended (the header
// becomes the union of old and new columns, in first-seen order; cells of missing columns stay empty),
// everything is written to "<file>.tmp.<pid>" in the same directory, flushed and fsync'ed, then rename()d
// over the original. A crash at any point leaves either the old or the new file, never a truncated one.
// Quoting follows RFC 4180 (fields with , " CR LF are quoted, quotes doubled).
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace sb {

/// One row: ordered (column, value) pairs. Order is the column order for a new file.
using CsvRow = std::vector<std::pair<std::string, std::string>>;

struct CsvTable {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows; ///< each row has header.size() cells
};

class CsvWriter {
public:
    /// Appends rows to `path` (creating it). Throws sb::Error(ExitCode::Failure) naming the path and
    /// the OS error when the directory is missing or unwritable; the original file is then untouched.
    static void appendRows(const std::string& path, const std::vector<CsvRow>& rows);
    /// Checks up front that `path` can be written (directory exists and is writable, file writable if
    /// present), so a bad --csv fails before minutes of measuring. Throws like appendRows.
    static void checkWritable(const std::string& path);
    /// Parses a CSV file written by appendRows (RFC 4180). Throws on a missing file or ragged rows.
    static CsvTable read(const std::string& path);
    static CsvTable parse(const std::string& text, const std::string& sourceName);
    /// Writes `table` to `path`, replacing any existing file atomically with the same temp file, fsync,
    /// rename and directory fsync steps as appendRows (an existing file keeps its mode). Every row must
    /// have header.size() cells. Throws like appendRows; on failure no temp file is left and the old
    /// file, if any, is untouched.
    static void writeTable(const std::string& path, const CsvTable& table);
    /// The exact text appendRows writes for `table`: header line, then one line per row, RFC 4180
    /// quoting, LF line ends.
    static std::string serialize(const CsvTable& table);
    /// Rows as a table: the header is the union of their columns in first-seen order, missing cells
    /// empty (the same merge appendRows does into an existing file).
    static CsvTable toTable(const std::vector<CsvRow>& rows);
    /// Replaces `path` with `text` atomically (temp file, fsync, rename, directory fsync): for the
    /// other formats of the same rows (bench export -o). Throws like appendRows.
    static void writeText(const std::string& path, const std::string& text);
    static std::string quote(const std::string& field);
};

} // namespace sb
