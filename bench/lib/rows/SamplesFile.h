#pragma once
// --samples FILE: per-frame samples (one row per measured frame) for distributions and re-analysis.
// Raw timer-query values are kept here with the verdict beside them, under names that say "timer"
// rather than "gpu" when the verdict is not "trusted".
#include <string>

#include "bench/lib/harness/MeasuredHarness.h"

namespace sb {

class SamplesFile {
public:
    static void append(const std::string& path, const MeasuredHarness& harness, const RunResult& result);
};

} // namespace sb
