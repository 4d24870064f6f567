// libFuzzer target: the CSV reader behind `bench merge` and `bench export` (CsvWriter::parse,
// bench/lib/output/CsvWriter.h) over arbitrary text. Bad input (ragged rows, an unterminated quote) must end
// in sb::Error. What parses is written back with CsvWriter::serialize, which must read back to the same
// table: merge and export rewrite every file they read, and a cell that changed on the way (a quote,
// a CR, an empty last column) would be a silently altered result. Seeds: fuzz/corpus/csv_parse/.
// CsvMerge has no text entry point (it reads and writes files), so it is not fuzzed here.
#include <cstddef>
#include <cstdint>
#include <string>

#include "bench/lib/output/CsvWriter.h"
#include "core/Error.h"
#include "fuzz/FuzzReach.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text = sb::fuzz::text(data, size);
    try {
        const sb::CsvTable table = sb::CsvWriter::parse(text, "fuzz.csv");
        const std::string written = sb::CsvWriter::serialize(table);
        const sb::CsvTable again = sb::CsvWriter::parse(written, "fuzz.csv (written back)");
        sb::fuzz::require(again.header == table.header && again.rows == table.rows,
                          "CSV does not read back as written:\n" + written);
        sb::fuzz::reached(sb::fuzz::Outcome::Parsed, std::to_string(table.header.size()) + " columns, " +
                                                         std::to_string(table.rows.size()) + " rows");
    } catch (const sb::Error& e) {
        sb::fuzz::reached(sb::fuzz::Outcome::Rejected, e.what());
    }
    return 0;
}
