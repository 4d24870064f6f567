#pragma once
// The worker side of a sweep (`bench sweep-worker JOB.json`, started by SweepRunner, not by people):
// one process, one harness, the job's rows in order, each appended to the sweep's CSV the moment it is
// measured, progress on stdout in the protocol of SweepJob.h. The first failure ends the worker with
// that error's exit code after reporting it; the runner records it and starts a new worker for the
// rest, so one bad configuration costs one row, never the context of the next.
//
// Fault injection for the tests of that machinery: SHADOWBENCH_FAULT_INJECT="crash:<config_index>"
// raises SIGSEGV, "glerror:<config_index>" issues an invalid GL call (caught by the debug output like
// any GL error), just before that configuration is measured.
#include <string>

namespace sb {

class SweepWorker {
public:
    /// Runs the job file; returns the process exit code.
    static int run(const std::string& jobPath);
};

} // namespace sb
