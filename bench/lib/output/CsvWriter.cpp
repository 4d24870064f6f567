#include "bench/lib/output/CsvWriter.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "bench/lib/output/AtomicFile.h"
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

/// A path that names no file (or a folder) is wrong input (exit 2) like any other; a file that exists
/// and still cannot be read is a failure of the run (exit 1).
[[noreturn]] void failRead(const std::string& path, int err) {
    const bool wrongPath = err == ENOENT || err == ENOTDIR || err == EISDIR;
    throw Error("cannot read CSV '" + path + "': " + std::strerror(err),
                wrongPath ? ExitCode::BadInput : ExitCode::Failure);
}

// Reads the whole file for merge and export. A device is refused before it is opened (/dev/zero would
// be read forever); a FIFO is read to its end (process substitution hands one over).
std::string readWhole(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) failRead(path, errno);
    if (S_ISDIR(st.st_mode)) failRead(path, EISDIR);
    if (!S_ISREG(st.st_mode) && !S_ISFIFO(st.st_mode))
        throw Error("cannot read CSV '" + path + "': not a regular file");
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) failRead(path, errno);
    std::string text;
    char buf[1 << 16];
    int err = 0;
    for (;;) {
        ssize_t n = ::read(fd, buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) err = errno;
        if (n <= 0) break;
        text.append(buf, size_t(n));
    }
    ::close(fd);
    if (err) failRead(path, err);
    return text;
}

// RFC 4180 reader. Records end at LF or CRLF (a lone CR is accepted too); quoted fields may hold
// separators, doubled quotes and line breaks. Line numbers count physical lines, so an error points
// at the line an editor shows.
class Parser {
public:
    Parser(const std::string& text, const std::string& source) : mText(text), mSource(source) {
        if (mText.compare(0, 3, kUtf8Bom) == 0) mPos = 3; // spreadsheet programs prepend one
    }

    /// Next record and the line it starts on; false at the end of the text. Blank lines are skipped:
    /// the writer quotes a lone empty cell (""), so a blank line never stands for data.
    bool next(std::vector<std::string>& record, size_t& line) {
        while (mPos < mText.size() && consumeLineBreak()) {
        }
        if (mPos >= mText.size()) return false;
        record.clear();
        line = mLine;
        do record.push_back(peek() == kQuote ? quotedField() : plainField());
        while (consume(kSeparator));
        if (mPos < mText.size() && !consumeLineBreak())
            fail(mLine, "unexpected character after a quoted field");
        return true;
    }

    [[noreturn]] void fail(size_t line, const std::string& why) const {
        throw Error(mSource + ":" + std::to_string(line) + ": " + why);
    }

private:
    char peek() const { return mPos < mText.size() ? mText[mPos] : '\0'; }
    bool consume(char c) {
        if (mPos >= mText.size() || mText[mPos] != c) return false;
        ++mPos;
        return true;
    }
    bool consumeLineBreak() {
        bool cr = consume('\r');
        bool lf = consume('\n');
        if (!cr && !lf) return false;
        ++mLine;
        return true;
    }

    std::string plainField() {
        size_t end = mText.find_first_of(kNeedsQuoting, mPos);
        if (end == std::string::npos) end = mText.size();
        if (end < mText.size() && mText[end] == kQuote) fail(mLine, "'\"' inside an unquoted field");
        std::string field = mText.substr(mPos, end - mPos);
        mPos = end;
        return field;
    }

    std::string quotedField() {
        size_t startLine = mLine;
        std::string field;
        ++mPos; // opening quote
        for (;;) {
            if (mPos >= mText.size()) fail(startLine, "quoted field is not closed");
            char c = mText[mPos++];
            if (c == kQuote && !consume(kQuote)) return field; // "" is an escaped quote
            if (c == '\n') ++mLine;
            field += c;
        }
    }

    const std::string& mText;
    const std::string& mSource;
    size_t mPos = 0;
    size_t mLine = 1;
};

// ---------------------------------------------------------------------------------------------------
// Merging and writing

size_t columnIndex(const std::vector<std::string>& header, const std::string& column) {
    return size_t(std::find(header.begin(), header.end(), column) - header.begin());
}

// Header union in first-seen order: old columns keep their place, new ones follow in the order the new
// rows name them. Old rows get empty cells for the new columns; new rows leave absent columns empty.
void mergeRows(CsvTable& table, const std::vector<CsvRow>& rows, const std::string& path) {
    for (const CsvRow& row : rows)
        for (const auto& cell : row)
            if (columnIndex(table.header, cell.first) == table.header.size())
                table.header.push_back(cell.first);
    for (auto& old : table.rows) old.resize(table.header.size());
    for (const CsvRow& row : rows) {
        std::vector<std::string> cells(table.header.size());
        std::vector<bool> seen(table.header.size(), false);
        for (const auto& [column, value] : row) {
            size_t i = columnIndex(table.header, column);
            // Two values for one column would silently drop one measurement: a bug in the caller.
            if (seen[i]) failWrite(path, "a new row names column '" + column + "' twice", 0);
            seen[i] = true;
            cells[i] = value;
        }
        table.rows.push_back(std::move(cells));
    }
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

// Read, merge and replace all happen under the file's lock (bench/lib/output/AtomicFile.h), so two processes
// appending to one file both keep their rows.
void CsvWriter::appendRows(const std::string& path, const std::vector<CsvRow>& rows) {
    if (rows.empty()) return; // nothing to add, and no header to create a new file with
    AtomicFile file(path, "CSV");
    // A corrupt existing file is an error (BadInput, naming file and line), never silently replaced.
    CsvTable table = parse(file.read(), path);
    mergeRows(table, rows, path);
    file.replace(serialize(table));
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
    return parse(readWhole(path), path);
}

CsvTable CsvWriter::parse(const std::string& text, const std::string& sourceName) {
    Parser parser(text, sourceName);
    CsvTable table;
    std::vector<std::string> record;
    size_t line = 0;
    if (!parser.next(table.header, line)) return table; // empty text: no header, no rows
    for (size_t i = 0; i < table.header.size(); ++i)
        if (columnIndex(table.header, table.header[i]) != i)
            parser.fail(line, "column '" + table.header[i] + "' appears twice in the header");
    while (parser.next(record, line)) {
        if (record.size() != table.header.size())
            parser.fail(line, "row has " + std::to_string(record.size()) + " fields but the header has " +
                                  std::to_string(table.header.size()));
        table.rows.push_back(record);
    }
    return table;
}

} // namespace sb
