#pragma once
// Facts about the machine and build recorded in every CSV row (docs/ARCHITECTURE.md, "Results").
#include <string>

namespace sb {

struct Environment {
    std::string timestamp; ///< ISO 8601 UTC, when the row was measured
    std::string
        gitCommit;        ///< the commit the binary was built from (bench/lib/rows/BuildInfo.h), or "unknown"
    std::string cpuModel; ///< /proc/cpuinfo "model name"
    int hardwareThreads = 0;
    std::string lpNumThreads; ///< LP_NUM_THREADS if set (llvmpipe rasteriser threads), else ""
    static Environment capture();
    static std::string nowIso8601();
};

} // namespace sb
