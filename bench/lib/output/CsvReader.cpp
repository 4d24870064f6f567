#include "bench/lib/output/CsvReader.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <iostream>
#include <sys/stat.h>
#include <unistd.h>
#include <unordered_map>

#include "core/Error.h"

namespace sb {

namespace {

constexpr char kSeparator = ',';
constexpr char kQuote = '"';
constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";
constexpr size_t kChunkBytes = size_t(1) << 16;
constexpr int kEnd = -1;

/// Thrown inside the reader when the source ends in the middle of a record without a final line break.
struct PartialLastLine {};

bool endsInLineBreak(std::string_view lastChunk) {
    return !lastChunk.empty() && (lastChunk.back() == '\n' || lastChunk.back() == '\r');
}

/// A path that names no file (or a folder) is wrong input (exit 2) like any other; a file that exists
/// and still cannot be read is a failure of the run (exit 1).
[[noreturn]] void failRead(const std::string& path, int err) {
    const bool wrongPath = err == ENOENT || err == ENOTDIR || err == EISDIR;
    throw Error("cannot read CSV '" + path + "': " + std::strerror(err),
                wrongPath ? ExitCode::BadInput : ExitCode::Failure);
}

} // namespace

CsvReader::CsvReader(const std::string& path) : mSource(path), mOwnsFd(true) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) failRead(path, errno);
    if (S_ISDIR(st.st_mode)) failRead(path, EISDIR);
    if (!S_ISREG(st.st_mode) && !S_ISFIFO(st.st_mode))
        throw Error("cannot read CSV '" + path + "': not a regular file");
    mRegular = S_ISREG(st.st_mode);
    mFd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY);
    if (mFd < 0) failRead(path, errno);
}

CsvReader::CsvReader(int fd, std::string source) : mSource(std::move(source)), mFd(fd), mRegular(true) {}

CsvReader::CsvReader(std::string_view text, std::string source)
    : mSource(std::move(source)), mRequireNewline(false), mText(text), mEof(true) {}

CsvReader::~CsvReader() {
    if (mOwnsFd && mFd >= 0) ::close(mFd);
}

void CsvReader::fail(size_t line, const std::string& why) const {
    throw Error(mSource + ":" + std::to_string(line) + ": " + why);
}

// A borrowed descriptor is read with pread, so its file offset (the owner's) is left alone.
bool CsvReader::refill() {
    if (mEof) return false;
    mBuffer.resize(kChunkBytes);
    for (;;) {
        ssize_t n = mOwnsFd ? ::read(mFd, mBuffer.data(), kChunkBytes)
                            : ::pread(mFd, mBuffer.data(), kChunkBytes, mOffset);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) failRead(mSource, errno);
        if (n == 0) {
            mEof = true;
            return false;
        }
        mOffset += n;
        mText = std::string_view(mBuffer.data(), size_t(n));
        mPos = 0;
        return true;
    }
}

int CsvReader::peek() {
    if (mPos >= mText.size() && !refill()) return kEnd;
    return static_cast<unsigned char>(mText[mPos]);
}

int CsvReader::get() {
    int c = peek();
    if (c != kEnd) ++mPos;
    return c;
}

bool CsvReader::consume(char c) {
    if (peek() != static_cast<unsigned char>(c)) return false;
    get();
    return true;
}

bool CsvReader::consumeLineBreak() {
    bool cr = consume('\r');
    bool lf = consume('\n');
    if (!cr && !lf) return false;
    ++mLine;
    return true;
}

void CsvReader::grow(size_t bytes) {
    mRecordBytes += bytes;
    if (mRecordBytes > kMaxRecordBytes)
        fail(mRecordLine, "row longer than " + std::to_string(kMaxRecordBytes >> 20) + " MiB");
}

// Whole runs of plain bytes are copied at once: this loop is what a million-row file costs.
void CsvReader::plainField(std::string& field) {
    for (;;) {
        if (peek() == kEnd) return;
        size_t start = mPos, end = mPos;
        while (end < mText.size()) {
            char c = mText[end];
            if (c == kSeparator || c == '\r' || c == '\n') break;
            if (c == kQuote) fail(mLine, "'\"' inside an unquoted field");
            ++end;
        }
        grow(end - start);
        field.append(mText.data() + start, end - start);
        mPos = end;
        if (end < mText.size()) return;
    }
}

void CsvReader::quotedField(std::string& field) {
    size_t startLine = mLine;
    get(); // opening quote
    for (;;) {
        int c = get();
        if (c == kEnd && mRequireNewline && !endsInLineBreak(mText)) throw PartialLastLine{};
        if (c == kEnd) fail(startLine, "quoted field is not closed");
        if (c == kQuote && !consume(kQuote)) return; // "" is an escaped quote
        if (c == '\n') ++mLine;
        grow(1);
        field += char(c);
    }
}

// A file's last line without a line break is what a writer killed during an in-place append leaves:
// it is not a row, so it is skipped with a warning (a sweep's --resume then measures that
// configuration again) and the next append cuts it (CsvWriter::appendRows).
bool CsvReader::next(std::vector<std::string>& record) {
    try {
        return readRecord(record);
    } catch (const PartialLastLine&) {
        std::cerr << "bench: warning: " << mSource << ":" << mRecordLine
                  << ": ignoring a partial last line without a line break (a writer killed while appending "
                     "it; the next append cuts it)\n";
        return false;
    }
}

bool CsvReader::readRecord(std::vector<std::string>& record) {
    if (mLine == 1 && mRecordLine == 0 && mPos == 0 && peek() != kEnd &&
        mText.substr(0, kUtf8Bom.size()) == kUtf8Bom)
        mPos = kUtf8Bom.size(); // spreadsheet programs prepend one
    while (consumeLineBreak()) {
    }
    if (peek() == kEnd) return false;
    mRecordLine = mLine;
    mRecordBytes = 0;
    size_t fields = 0;
    for (;; ++fields) {
        if (fields == record.size()) record.emplace_back();
        std::string& field = record[fields];
        field.clear();
        if (peek() == kQuote)
            quotedField(field);
        else
            plainField(field);
        if (consume(kSeparator)) continue;
        if (consumeLineBreak()) break;
        if (peek() != kEnd) fail(mLine, "unexpected character after a quoted field");
        if (mRequireNewline) throw PartialLastLine{};
        break;
    }
    record.resize(fields + 1);
    return true;
}

std::vector<std::string> CsvReader::header() {
    std::vector<std::string> header;
    if (!next(header)) return header;
    std::unordered_map<std::string_view, size_t> seen;
    seen.reserve(header.size());
    for (const std::string& name : header)
        if (!seen.emplace(name, 0).second)
            fail(mRecordLine, "column '" + name + "' appears twice in the header");
    return header;
}

} // namespace sb
