#pragma once
// The `bench` command: parses the command line into a RunConfig, then measures each technique in turn
// on one Harness, printing the table and appending CSV rows as each technique finishes (a later
// failure never loses earlier rows).
#include <string>
#include <vector>

#include "bench/RunConfig.h"

namespace sb {

class BenchApp {
public:
    /// Runs the command; returns the process exit code. Prints errors as one line on stderr.
    static int main(int argc, char** argv);
    /// Picks the subcommand (accuracy, sweep, bottleneck, figures, merge, export) or a plain run.
    static int dispatch(int argc, char** argv);
    /// Parses arguments into `config`. Returns -1 to continue, or an exit code when the command is
    /// finished (--help, --list, a parse error). Throws sb::Error for bad values.
    static int parse(int argc, char** argv, RunConfig& config, bool& listOnly);
    /// Measures every technique of `config` (the body of `bench` and `bench accuracy`, which also
    /// judges each against the reference), round by round when --repeat asks for several.
    static int run(const RunConfig& config);
    /// The technique specs a run measures: config.techniques, each expanded over its quality knobs
    /// with `bench accuracy --sweep`.
    static std::vector<TechniqueSpec> configurations(const RunConfig& config);
    /// parse() over a list of options (no program name): the sweep checks and the worker use it.
    static RunConfig parseArgs(const std::vector<std::string>& args, RunConfig::Mode mode);
    /// "1024x768" -> (1024, 768); throws sb::Error naming the option.
    static std::pair<int, int> parseSize(const std::string& text);
};

} // namespace sb
