#pragma once
// The `bench` command line: one table of its modes (BenchApp.cpp: name, usage, one-line summary, entry
// point), the dispatch to them and the convention that turns errors into exit codes. `bench --help`
// lists the modes from the same table.
#include <string>
#include <vector>

#include "bench/lib/options/CliCatalog.h"
#include "bench/lib/options/ManPage.h"

namespace sb {

class BenchApp {
public:
    /// Runs the command; returns the process exit code. Prints errors as one line on stderr.
    static int main(int argc, char** argv);
    /// Picks the mode by argv[1] (accuracy, sweep, bottleneck, figures, merge, export) or a plain run,
    /// and hands it argv from its own name on, as if it were a program of its own.
    static int dispatch(int argc, char** argv);
    /// Fixes glibc's heap trim and mmap thresholds (BenchApp.cpp says why: heap trimming churn made
    /// frame times depend on heap layout). Called by main() and by handloop.
    /// `bench --version`: version, the commit the binary was built from (bench/lib/rows/BuildInfo.h), build
    /// type and compiler, and the folder its shaders and scenes are read from.
    static std::string versionText();
    /// The end of `bench --help`: the modes, examples and exit codes.
    static std::string helpFooter();
    /// Every listed mode with the options of its CLI::App, built without parsing (CliCatalog.h): what
    /// the man page and the bash completion are written from.
    static std::vector<CliCommand> catalog();
    /// The man page's parts that only the dispatcher knows: version line, examples, exit codes.
    static ManPage::Text manPageText();
};

} // namespace sb
