#pragma once
// bench(1): the man page, written in roff from the same tables as --help (CliCatalog.h: every mode's
// options) and the registry (the built-in techniques, their properties, the built-in scenes), so it
// cannot drift from the binary. `bench --man` prints it; cmake/ManAndCompletion.cmake runs that at build
// time into build/bench.1 and installs it as share/man/man1/bench.1.gz.
#include <string>
#include <vector>

#include "bench/lib/options/CliCatalog.h"

namespace sb {

class ManPage {
public:
    /// What the dispatcher alone knows (bench/BenchApp.cpp).
    struct Text {
        std::string version;   ///< "shadowbench 0.1.0": the footer of every page
        std::string examples;  ///< --help's "Examples:" block: "  COMMAND   what it does" per line
        std::string exitCodes; ///< --help's "Exit codes: ..." paragraph
    };
    /// The whole page: NAME, SYNOPSIS, DESCRIPTION, OPTIONS (the plain run), one section per other mode,
    /// TECHNIQUES, SCENES, EXIT STATUS, EXAMPLES, FILES, SEE ALSO. `commands[0]` is the plain run.
    static std::string render(const std::vector<CliCommand>& commands, const Text& text);
    /// `text` safe as roff running text: backslashes, a leading '.' or '\'' and hyphens escaped.
    static std::string escape(const std::string& text);
};

} // namespace sb
