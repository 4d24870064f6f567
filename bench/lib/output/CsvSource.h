#pragma once
// The rows of a result CSV read one at a time, as often as a writer needs passes over them (a JSON
// export types its columns in one pass and writes in the next), without holding the file: each pass
// reads it again through bench/lib/output/CsvReader.h. A FIFO cannot be read twice, so its text is held
// (process substitution hands small files over); a table in memory serves the same interface.
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "bench/lib/output/CsvWriter.h"

namespace sb {

/// Where exported text goes: stdout or the temp file of a replacement (bench/lib/output/AtomicFile.h).
using TextSink = std::function<void(std::string_view)>;

class CsvSource {
public:
    /// A row and the line it starts on ("<name>:<line>" in messages).
    using Visitor = std::function<void(const std::vector<std::string>& row, size_t line)>;

    /// Opens `path` and reads its header (errors as CsvWriter::read: BadInput for a missing file, a
    /// device or a malformed header).
    static CsvSource file(const std::string& path);
    /// Rows in memory; `table` must outlive the source. A row's line is its index + 2 (one line each).
    static CsvSource table(const CsvTable& table, std::string name = "(rows)");

    const std::string& name() const { return mName; }
    const std::vector<std::string>& header() const { return mHeader; }
    bool hasColumn(const std::string& column) const { return mIndex.count(column) != 0; }
    /// The cell of `row` in `column`; "" when there is no such column.
    const std::string& cell(const std::vector<std::string>& row, const std::string& column) const;
    /// Calls `visit` for every row in order; throws sb::Error(BadInput) naming "<name>:<line>" for a
    /// malformed or ragged row.
    void forEachRow(const Visitor& visit) const;

private:
    CsvSource() = default;
    void indexHeader();

    std::string mName;
    std::vector<std::string> mHeader;
    std::unordered_map<std::string, size_t> mIndex;
    const CsvTable* mTable = nullptr;   ///< rows in memory
    std::shared_ptr<std::string> mText; ///< a FIFO's content
};

} // namespace sb
