#pragma once
// Facts about the machine and build recorded in every CSV row (docs/ARCHITECTURE.md, "Results"), and
// where the row ran: the host and, inside Slurm, the job and array task, so that rows of a campaign
// spread over a cluster can be traced back to the node and task that measured them.
#include <string>

#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/rows/SlurmTask.h"

namespace sb {

struct Environment {
    std::string timestamp; ///< ISO 8601 UTC, when the row was measured
    std::string
        gitCommit;        ///< the commit the binary was built from (bench/lib/rows/BuildInfo.h), or "unknown"
    std::string cpuModel; ///< /proc/cpuinfo "model name"
    /// CPUs of the process's affinity mask (core/CpuAllocation.h): a Slurm task's or `taskset`'s share,
    /// not the node's count.
    int hardwareThreads = 0;
    std::string lpNumThreads; ///< LP_NUM_THREADS if set (llvmpipe rasteriser threads), else ""
    std::string host;         ///< gethostname()
    SlurmTask slurm;
    static Environment capture();
    static std::string nowIso8601();
    /// gethostname(), or "unknown" when it fails.
    static std::string hostName();
    /// The columns that say where a row ran (`host`, `slurm_job_id`, `slurm_array_task_id`), in the
    /// order of the column table: every measured row has them, and so does a row that says why a
    /// configuration has no numbers.
    CsvRow placeColumns() const;
};

} // namespace sb
