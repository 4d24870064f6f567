#pragma once
// How a sweep's rows reach its CSV, from the worker (measured rows) and from the runner (the rows of
// configurations that failed). A configuration has one row in the file: a retry (--retry-failed)
// replaces its failed row with the new one, ok or failed, in one atomic rewrite
// (CsvWriter::replaceRows), so `bench merge` and --resume never see a configuration twice and a crash
// never loses the old row before the new one is in. Rows that replace nothing are appended in place,
// the cheap path, whatever the file's size.
#include <string>
#include <vector>

#include "bench/lib/output/CsvWriter.h"

namespace sb {

class SweepRows {
public:
    /// Writes `rows` (each with its sweep_id and config_index) to `csvPath`. With `replaceFailed`, the
    /// file's rows of the same sweep_id and config_index whose status is failed are removed in the same
    /// rewrite; rows of any other status are never removed.
    static void write(const std::string& csvPath, const std::vector<CsvRow>& rows, bool replaceFailed);
};

} // namespace sb
