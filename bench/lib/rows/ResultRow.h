#pragma once
// Builds the CSV row of one measured configuration (docs/ARCHITECTURE.md, "Results"), its columns named and
// ordered as bench/lib/output/ResultColumns.h's table (docs/CSV.md describes every one). GPU times appear
// only when the timer verdict is "trusted"; otherwise those cells stay empty and timer_verdict/timer_reason
// say why (docs/ARCHITECTURE.md, "The timing contract": never present untrusted numbers as GPU time).
#include "bench/lib/harness/MeasuredHarness.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/rows/Environment.h"
#include "techniques/EffectCoverage.h"

namespace sb {

struct ResultRow {
    static CsvRow build(const MeasuredHarness& harness, const RunResult& result, const Environment& env);
    /// The same row from either API's run (bench/lib/harness/RowSource.h).
    static CsvRow build(const RowSource& source, const RunResult& result, const Environment& env);
    /// effects_requested, effects_delivered, effects_missing: in every row, measured or refused.
    static CsvRow effectColumns(const EffectCoverage& coverage);
};

} // namespace sb
