#pragma once
// What every mode of `bench` accepts, read from the very CLI::App its --help prints, without parsing or
// running anything: the man page (ManPage.h) and the bash completion (BashCompletion.h) are written
// from it, and the "did you mean" of an unknown option picks from it.
//
// A mode's entry point builds its CLI::App and hands it to parseCli (CliParse.h) before it does anything
// else. describe() runs the entry point with a capture switched on, under which parseCli records the app
// and returns 0 ("finished") instead of parsing: each command keeps declaring its options beside the
// code that uses them, and the catalog can never miss one.
#include <functional>
#include <string>
#include <vector>

// CLI11 2.1 defines its validators as objects in its header, which costs every file that includes it
// about 6 s of compiling at -O3: this header only names the class, so the man page, the completion and
// the dispatcher (which include it) do not pay for it.
namespace CLI {
class App;
}

namespace sb {

/// One option or positional argument as --help shows it.
struct CliOption {
    std::vector<std::string> flags; ///< "-t", "--technique"; empty for a positional argument
    std::string positional;         ///< the positional argument's name ("file"); empty for an option
    std::string argument;           ///< the value's type as --help names it ("TEXT", "INT"); "" for a flag
    std::string description;
    std::string defaultValue; ///< as --help shows it; "" when it shows none
    bool required = false;
    bool repeatable = false; ///< takes several values (a vector)
};

/// One mode: the dispatcher's table row (name, usage, summary) and the options of its CLI::App.
struct CliCommand {
    std::string name; ///< argv[1]; "" for the plain run
    std::string usage, summary;
    std::string description, footer; ///< the CLI::App's
    std::vector<CliOption> options;  ///< in --help's order, hidden ones left out
};

class CliCatalog {
public:
    /// Runs `entry` (a mode's main with a bare argv) with the capture on and returns the options of the
    /// CLI::App it built; `name`, `usage` and `summary` are copied in. Throws std::logic_error when
    /// the entry point never reached parseCli.
    static CliCommand describe(const std::function<int()>& entry, const std::string& name,
                               const std::string& usage, const std::string& summary);
    /// For parseCli: when a describe() is under way, records `app` and returns true (the caller then
    /// returns without parsing); otherwise false.
    static bool capture(const CLI::App& app);
    /// The option's names as typed: "-t", "--technique".
    static std::vector<std::string> optionNames(const CLI::App& app);
    /// The one line for arguments CLI11 did not expect (`app.remaining()` after its ExtrasError):
    /// "unknown option --instanses (did you mean --instances?)" for the first that looks like an
    /// option, else "unexpected argument WORD".
    static std::string unexpected(const CLI::App& app);
};

} // namespace sb
