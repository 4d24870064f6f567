#include "bench/output/CsvWriter.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <optional>
#include <sys/stat.h>
#include <unistd.h>

#include "core/Error.h"

namespace sb {

namespace {

constexpr char kSeparator = ',';
constexpr char kQuote = '"';
constexpr const char* kNeedsQuoting = ",\"\r\n";
constexpr const char* kUtf8Bom = "\xEF\xBB\xBF";
constexpr mode_t kNewFileMode = 0666; // the umask decides, as for any file the user creates

// I/O failures while writing results are run failures (ExitCode::Failure): the user asked for a
// sensible thing, the system refused. The message carries the path and the OS reason.
[[noreturn]] void failWrite(const std::string& path, const std::string& what, int err) {
    throw Error("cannot write CSV '" + path + "': " + what +
                    (err ? std::string(": ") + std::strerror(err) : ""),
                ExitCode::Failure);
}

[[noreturn]] void failRead(const std::string& path, int err) {
    throw Error("cannot read CSV '" + path + "': " + std::strerror(err), ExitCode::Failure);
}

std::string directoryOf(const std::string& path) {
    size_t slash = path.rfind('/');
    if (slash == std::string::npos) return ".";
    return slash == 0 ? "/" : path.substr(0, slash);
}

// The pid makes the name unique among concurrent writers; the temp lies in the target's directory
// because rename() is only atomic within one file system.
std::string tempPathFor(const std::string& path) {
    return path + ".tmp." + std::to_string(::getpid());
}

// ---------------------------------------------------------------------------------------------------
// Reading

struct FileContent {
    std::string text;
    mode_t mode = 0;
};

// Reads the whole file; nullopt when it does not exist (the first append creates it). Plain POSIX
// calls so errno is reliable for the message, and so a directory is reported as such (EISDIR) before
// anything is written.
std::optional<FileContent> readIfExists(const std::string& path, bool forWriting) {
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        if (errno == ENOENT) return std::nullopt;
        forWriting ? failWrite(path, "cannot read the existing file", errno) : failRead(path, errno);
    }
    FileContent out;
    struct stat st {};
    int err = ::fstat(fd, &st) != 0 ? errno : S_ISDIR(st.st_mode) ? EISDIR : 0;
    out.mode = st.st_mode & 07777;
    char buf[1 << 16];
    while (!err) {
        ssize_t n = ::read(fd, buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) err = errno;
        if (n <= 0) break;
        out.text.append(buf, size_t(n));
    }
    ::close(fd);
    if (err) forWriting ? failWrite(path, "cannot read the existing file", err) : failRead(path, err);
    return out;
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

bool writeAll(int fd, const std::string& text) {
    size_t done = 0;
    while (done < text.size()) {
        ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return false;
        done += size_t(n);
    }
    return true;
}

// Writes the temp file completely and durably. Raw write() has no user-space buffer, so fsync() alone
// is the "fflush + fsync" step. On failure the temp file is removed and the error thrown.
void writeTemp(const std::string& path, const std::string& tmp, const std::string& text,
               std::optional<mode_t> keepMode) {
    int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, kNewFileMode);
    if (fd < 0) failWrite(path, "cannot create temporary file '" + tmp + "'", errno);
    // Replacing the file must not change who may read it (best effort: a foreign-owned file may refuse).
    if (keepMode) (void)::fchmod(fd, *keepMode);
    int err = 0;
    if (!writeAll(fd, text) || ::fsync(fd) != 0) err = errno;
    if (::close(fd) != 0 && !err) err = errno;
    if (err) {
        ::unlink(tmp.c_str());
        failWrite(path, "cannot write temporary file '" + tmp + "'", err);
    }
}

// The rename is the commit point: before it readers see the old file, after it the new one. The
// directory is fsync'ed afterwards so the rename itself survives a power cut; that is best effort
// (some file systems refuse fsync on directories) because the data is already safe either way.
void commit(const std::string& path, const std::string& tmp) {
    if (::rename(tmp.c_str(), path.c_str()) != 0) {
        int err = errno;
        ::unlink(tmp.c_str());
        failWrite(path, "cannot rename '" + tmp + "' over it", err);
    }
    int dirFd = ::open(directoryOf(path).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dirFd >= 0) {
        (void)::fsync(dirFd);
        ::close(dirFd);
    }
}

void requireDirectory(const std::string& path, const std::string& dir) {
    struct stat st {};
    if (::stat(dir.c_str(), &st) != 0) failWrite(path, "directory '" + dir + "'", errno);
    if (!S_ISDIR(st.st_mode)) failWrite(path, "'" + dir + "'", ENOTDIR);
    if (::access(dir.c_str(), W_OK | X_OK) != 0) failWrite(path, "directory '" + dir + "'", errno);
}

void requireReplaceableFile(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        if (errno != ENOENT) failWrite(path, "cannot inspect it", errno);
        return;
    }
    if (S_ISDIR(st.st_mode)) failWrite(path, "it is a directory", 0);
    if (::access(path.c_str(), R_OK | W_OK) != 0) failWrite(path, "existing file", errno);
}

// Both ways of writing a file end here, so appends and whole-table writes are equally crash-safe.
void replaceFile(const std::string& path, const std::string& text, std::optional<mode_t> keepMode) {
    std::string tmp = tempPathFor(path);
    writeTemp(path, tmp, text, keepMode);
    commit(path, tmp);
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
    struct stat st {};
    std::optional<mode_t> keepMode;
    if (::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode)) keepMode = st.st_mode & 07777;
    replaceFile(path, text, keepMode);
}

std::string CsvWriter::quote(const std::string& field) {
    if (field.find_first_of(kNeedsQuoting) == std::string::npos) return field;
    std::string out(1, kQuote);
    for (char c : field) {
        if (c == kQuote) out += kQuote;
        out += c;
    }
    return out + kQuote;
}

// Concurrent appends by two processes to one file are not serialised (the later rename wins and the
// other's rows are lost); runs write one CSV each or run one after the other.
void CsvWriter::appendRows(const std::string& path, const std::vector<CsvRow>& rows) {
    if (rows.empty()) return; // nothing to add, and no header to create a new file with
    std::optional<FileContent> old = readIfExists(path, true);
    // A corrupt existing file is an error (BadInput, naming file and line), never silently replaced.
    CsvTable table = old ? parse(old->text, path) : CsvTable{};
    mergeRows(table, rows, path);
    replaceFile(path, serialize(table), old ? std::optional<mode_t>(old->mode) : std::nullopt);
}

// A ragged table would be written without complaint but could not be read back, so it is refused
// before anything touches the disk. Only the mode of the old file is needed, so stat() suffices
// where appendRows reads the whole file.
void CsvWriter::writeTable(const std::string& path, const CsvTable& table) {
    for (size_t i = 0; i < table.rows.size(); ++i)
        if (table.rows[i].size() != table.header.size())
            failWrite(path,
                      "row " + std::to_string(i + 1) + " has " + std::to_string(table.rows[i].size()) +
                          " cells but the header has " + std::to_string(table.header.size()),
                      0);
    writeText(path, serialize(table));
}

// Permission checks give the clear messages; the final probe (create and remove the temp file that
// appendRows will use) catches what they cannot see: read-only mounts, root on NFS, over-long names.
void CsvWriter::checkWritable(const std::string& path) {
    requireDirectory(path, directoryOf(path));
    requireReplaceableFile(path);
    std::string tmp = tempPathFor(path);
    int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, kNewFileMode);
    if (fd < 0) failWrite(path, "cannot create temporary file '" + tmp + "'", errno);
    ::close(fd);
    ::unlink(tmp.c_str());
}

CsvTable CsvWriter::read(const std::string& path) {
    std::optional<FileContent> content = readIfExists(path, false);
    if (!content) failRead(path, ENOENT);
    return parse(content->text, path);
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
