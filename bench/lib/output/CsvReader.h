#pragma once
// A result CSV read one record at a time (RFC 4180, as bench/lib/output/CsvWriter.h writes it), so that a
// file of a million rows is never held whole: exports, compare and the append's header read keep only
// the record in hand (docs/ARCHITECTURE.md, "Results").
//
// Records end at LF or CRLF (a lone CR is accepted too); quoted fields may hold separators, doubled
// quotes and line breaks. Blank lines are skipped (the writer quotes a lone empty cell, so a blank line
// never stands for data); a leading UTF-8 byte-order mark is skipped. Line numbers count physical lines,
// so an error points at the line an editor shows.
//
// A file (not a text in memory) ends in a newline: the writer always ends one, and a writer killed
// half-way through an in-place append leaves a partial last line. That line is not a row: it is skipped
// with one warning on stderr naming the file and line (so a sweep's --resume measures it again), and the
// next append cuts it (CsvWriter::appendRows).
#include <cstddef>
#include <string>
#include <string_view>
#include <sys/types.h>
#include <vector>

namespace sb {

class CsvReader {
public:
    /// Opens `path`. A device is refused before it is opened (/dev/zero would be read forever); a FIFO
    /// is read to its end (process substitution hands one over). Throws sb::Error: BadInput when the
    /// path names nothing or a folder, Failure when an existing file cannot be read.
    explicit CsvReader(const std::string& path);
    /// Reads through `fd` from offset 0 without taking it over (the locked descriptor of an append).
    CsvReader(int fd, std::string source);
    /// Reads `text` (which must outlive the reader); a missing final newline is accepted.
    CsvReader(std::string_view text, std::string source);
    ~CsvReader();
    CsvReader(const CsvReader&) = delete;
    CsvReader& operator=(const CsvReader&) = delete;

    /// The next record into `record`; false at the end. Throws sb::Error(BadInput) naming
    /// "<source>:<line>" for a malformed record or one longer than kMaxRecordBytes.
    bool next(std::vector<std::string>& record);
    /// The line the record last returned by next() starts on.
    size_t line() const { return mRecordLine; }
    const std::string& source() const { return mSource; }
    /// True when the source is a regular file (it can be opened again for a second pass).
    bool regularFile() const { return mRegular; }
    /// The header (first record), checked for duplicate names in linear time; empty for an empty
    /// source. Call once, before the first next().
    std::vector<std::string> header();

    [[noreturn]] void fail(size_t line, const std::string& why) const;

    /// A record is bounded so that a file without line breaks cannot take all memory.
    static constexpr size_t kMaxRecordBytes = size_t(256) << 20;

private:
    int peek();
    int get();
    bool consume(char c);
    bool consumeLineBreak();
    bool refill();
    void plainField(std::string& field);
    void quotedField(std::string& field);
    void grow(size_t bytes);
    bool readRecord(std::vector<std::string>& record);

    std::string mSource;
    int mFd = -1;
    bool mOwnsFd = false;
    bool mRegular = false;
    bool mRequireNewline = true;
    off_t mOffset = 0; ///< next byte to read from the descriptor
    std::string mBuffer;
    std::string_view mText; ///< the unread part of the current chunk (or the whole text)
    size_t mPos = 0;
    bool mEof = false;
    size_t mLine = 1;
    size_t mRecordLine = 0;
    size_t mRecordBytes = 0;
};

} // namespace sb
