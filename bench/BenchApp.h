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
    /// Parses arguments into `config`. Returns -1 to continue, or an exit code when the command is
    /// finished (--help, --list, a parse error). Throws sb::Error for bad values.
    static int parse(int argc, char** argv, RunConfig& config, bool& listOnly);
    /// Measures every technique of `config` (the body of a normal run).
    static int run(const RunConfig& config);
    /// `bench accuracy`: measures and judges every technique (or every sweep configuration).
    static int runAccuracy(const RunConfig& config);
    /// "1024x768" -> (1024, 768); throws sb::Error naming the option.
    static std::pair<int, int> parseSize(const std::string& text);
};

} // namespace sb
