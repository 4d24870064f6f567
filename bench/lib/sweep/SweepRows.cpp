#include "bench/lib/sweep/SweepRows.h"

#include <algorithm>
#include <set>
#include <utility>

#include "bench/lib/output/ResultColumns.h"

namespace sb {

namespace {

using RowKey = std::pair<std::string, std::string>; ///< sweep_id, config_index

std::string valueOf(const CsvRow& row, const char* column) {
    for (const auto& [k, v] : row)
        if (k == column) return v;
    return "";
}

std::string cellOf(const std::vector<std::string>& header, const std::vector<std::string>& cells,
                   const char* column) {
    const auto it = std::find(header.begin(), header.end(), column);
    return it == header.end() ? "" : cells[size_t(it - header.begin())];
}

} // namespace

void SweepRows::write(const std::string& csvPath, const std::vector<CsvRow>& rows, bool replaceFailed) {
    if (!replaceFailed) return CsvWriter::appendRows(csvPath, rows);
    std::set<RowKey> replaced;
    for (const CsvRow& row : rows)
        replaced.emplace(valueOf(row, col::kSweepId), valueOf(row, col::kConfigIndex));
    CsvWriter::replaceRows(
        csvPath,
        [&](const std::vector<std::string>& header, const std::vector<std::string>& cells) {
            return cellOf(header, cells, col::kStatus) == col::kStatusFailed &&
                   replaced.count(
                       {cellOf(header, cells, col::kSweepId), cellOf(header, cells, col::kConfigIndex)});
        },
        rows);
}

} // namespace sb
