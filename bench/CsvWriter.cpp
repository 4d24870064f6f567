#include "bench/CsvWriter.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "scenes/Error.h"

namespace sb {

namespace {
namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& path, const std::string& what, int err) {
    throw Error("cannot write CSV '" + path + "': " + what + (err ? std::string(": ") + std::strerror(err) : ""),
                ExitCode::Failure);
}

std::string directoryOf(const std::string& path) {
    fs::path dir = fs::path(path).parent_path();
    return dir.empty() ? "." : dir.string();
}

std::string serialize(const CsvTable& t) {
    std::string out;
    auto line = [&](const std::vector<std::string>& cells) {
        for (size_t i = 0; i < cells.size(); ++i) {
            if (i) out += ',';
            out += CsvWriter::quote(cells[i]);
        }
        out += '\n';
    };
    line(t.header);
    for (const auto& r : t.rows) line(r);
    return out;
}

// Writes `text` to a temp file beside `path`, fsyncs it and renames it over `path`; the directory is
// fsync'ed afterwards (best effort) so the rename itself survives a power cut.
void writeAtomically(const std::string& path, const std::string& text) {
    std::string tmp = path + ".tmp." + std::to_string(getpid());
    int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) fail(path, "cannot create temporary file '" + tmp + "'", errno);
    size_t done = 0;
    while (done < text.size()) {
        ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            int err = errno;
            ::close(fd);
            ::unlink(tmp.c_str());
            fail(path, "write failed", err);
        }
        done += size_t(n);
    }
    if (::fsync(fd) != 0 || ::close(fd) != 0) {
        int err = errno;
        ::unlink(tmp.c_str());
        fail(path, "fsync/close failed", err);
    }
    if (::rename(tmp.c_str(), path.c_str()) != 0) {
        int err = errno;
        ::unlink(tmp.c_str());
        fail(path, "rename failed", err);
    }
    int dfd = ::open(directoryOf(path).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dfd >= 0) {
        ::fsync(dfd);
        ::close(dfd);
    }
}
} // namespace

std::string CsvWriter::quote(const std::string& field) {
    if (field.find_first_of(",\"\r\n") == std::string::npos) return field;
    std::string out = "\"";
    for (char c : field) {
        if (c == '"') out += '"';
        out += c;
    }
    return out + "\"";
}

void CsvWriter::checkWritable(const std::string& path) {
    std::string dir = directoryOf(path);
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) fail(path, "directory '" + dir + "' does not exist", 0);
    if (::access(dir.c_str(), W_OK) != 0) fail(path, "directory '" + dir + "' is not writable", errno);
    if (fs::exists(path, ec)) {
        if (fs::is_directory(path, ec)) fail(path, "it is a directory", 0);
        if (::access(path.c_str(), R_OK | W_OK) != 0) fail(path, "file is not readable and writable", errno);
    }
}

void CsvWriter::appendRows(const std::string& path, const std::vector<CsvRow>& rows) {
    checkWritable(path);
    CsvTable table;
    std::error_code ec;
    if (fs::exists(path, ec) && fs::file_size(path, ec) > 0) table = read(path);
    // Union header in first-seen order; cells of columns a row lacks stay empty.
    for (const CsvRow& row : rows)
        for (const auto& [col, value] : row)
            if (std::find(table.header.begin(), table.header.end(), col) == table.header.end())
                table.header.push_back(col);
    for (auto& r : table.rows) r.resize(table.header.size());
    for (const CsvRow& row : rows) {
        std::vector<std::string> cells(table.header.size());
        for (const auto& [col, value] : row)
            cells[size_t(std::find(table.header.begin(), table.header.end(), col) - table.header.begin())] = value;
        table.rows.push_back(std::move(cells));
    }
    writeAtomically(path, serialize(table));
}

CsvTable CsvWriter::read(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("cannot read CSV '" + path + "': " + std::strerror(errno), ExitCode::Failure);
    std::stringstream ss;
    ss << in.rdbuf();
    return parse(ss.str(), path);
}

CsvTable CsvWriter::parse(const std::string& text, const std::string& sourceName) {
    std::vector<std::vector<std::string>> records;
    std::vector<std::string> record;
    std::string field;
    bool quoted = false, fieldStarted = false;
    size_t line = 1;
    auto endField = [&] {
        record.push_back(std::move(field));
        field.clear();
        fieldStarted = false;
    };
    for (size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (quoted) {
            if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
                field += '"';
                ++i;
            } else if (c == '"') {
                quoted = false;
            } else {
                if (c == '\n') ++line;
                field += c;
            }
        } else if (c == '"' && !fieldStarted) {
            quoted = fieldStarted = true;
        } else if (c == ',') {
            endField();
        } else if (c == '\n' || c == '\r') {
            if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
            endField();
            records.push_back(std::move(record));
            record.clear();
            ++line;
        } else {
            field += c;
            fieldStarted = true;
        }
    }
    if (quoted) throw Error(sourceName + ": line " + std::to_string(line) + ": unterminated quoted field");
    if (fieldStarted || !record.empty()) {
        endField();
        records.push_back(std::move(record));
    }
    CsvTable t;
    if (records.empty()) return t;
    t.header = std::move(records.front());
    for (size_t r = 1; r < records.size(); ++r) {
        if (records[r].size() != t.header.size())
            throw Error(sourceName + ": record " + std::to_string(r + 1) + " has " + std::to_string(records[r].size()) +
                        " fields, the header has " + std::to_string(t.header.size()));
        t.rows.push_back(std::move(records[r]));
    }
    return t;
}

} // namespace sb
