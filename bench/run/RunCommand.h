#pragma once
// `bench [options]` and `bench accuracy [options]`: parses the options (RunOptions), then measures
// each technique in turn on one Harness, printing the table and appending CSV rows as each technique
// finishes (a later failure never loses earlier rows). `bench accuracy` also judges each against the
// Embree reference; `--window` shows the techniques in the viewer instead of measuring them.
#include <vector>

#include "bench/lib/options/RunConfig.h"

namespace sb {

class RunCommand {
public:
    /// argv from the program name on (`bench ...`, or `accuracy ...` for Mode::Accuracy). `modesFooter`
    /// ends `bench --help` (the dispatcher's list of modes and examples). Returns the exit code; errors
    /// are thrown as sb::Error.
    static int main(int argc, char** argv, RunConfig::Mode mode, const std::string& modesFooter);
    /// Measures every technique of `config`, round by round when --repeat asks for several. A technique
    /// that throws sb::Error is reported (row, console line) and the others still run; the exit code is
    /// then the worst of the refusals (1 over 2 over 3), else 0. When no technique could be measured,
    /// the worst error is thrown, as a single technique's always was.
    static int run(const RunConfig& config);
    /// The technique specs a run measures: config.techniques, each expanded over its quality knobs
    /// with `bench accuracy --sweep`.
    static std::vector<TechniqueSpec> configurations(const RunConfig& config);
};

} // namespace sb
