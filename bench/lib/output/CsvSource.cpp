#include "bench/lib/output/CsvSource.h"

#include <sys/stat.h>

#include "bench/lib/output/CsvReader.h"

namespace sb {

namespace {

const std::string kEmpty;

void requireWidth(const CsvReader& reader, const std::vector<std::string>& record, size_t width) {
    if (record.size() != width)
        reader.fail(reader.line(), "row has " + std::to_string(record.size()) +
                                       " fields but the header has " + std::to_string(width));
}

} // namespace

CsvSource CsvSource::file(const std::string& path) {
    CsvSource source;
    source.mName = path;
    CsvReader reader(path);
    if (!reader.regularFile()) {
        // Read once, to its end: the passes read the held text.
        CsvTable table = CsvWriter::readTable(reader, [](const std::string&) { return true; });
        source.mText = std::make_shared<std::string>(CsvWriter::serialize(table));
        source.mHeader = table.header;
    } else {
        source.mHeader = reader.header();
    }
    source.indexHeader();
    return source;
}

CsvSource CsvSource::table(const CsvTable& table, std::string name) {
    CsvSource source;
    source.mName = std::move(name);
    source.mTable = &table;
    source.mHeader = table.header;
    source.indexHeader();
    return source;
}

void CsvSource::indexHeader() {
    mIndex.reserve(mHeader.size());
    for (size_t i = 0; i < mHeader.size(); ++i) mIndex.emplace(mHeader[i], i);
}

const std::string& CsvSource::cell(const std::vector<std::string>& row, const std::string& column) const {
    auto it = mIndex.find(column);
    return it == mIndex.end() ? kEmpty : row[it->second];
}

void CsvSource::forEachRow(const Visitor& visit) const {
    if (mTable) {
        for (size_t i = 0; i < mTable->rows.size(); ++i) visit(mTable->rows[i], i + 2);
        return;
    }
    std::unique_ptr<CsvReader> reader = mText ? std::make_unique<CsvReader>(std::string_view(*mText), mName)
                                              : std::make_unique<CsvReader>(mName);
    reader->header();
    std::vector<std::string> record;
    while (reader->next(record)) {
        requireWidth(*reader, record, mHeader.size());
        visit(record, reader->line());
    }
}

} // namespace sb
