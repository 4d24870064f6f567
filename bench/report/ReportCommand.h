#pragma once
// `bench report DIR... [-o PAGE.html] [--title T] [--embed]`: one static HTML page from the result
// CSVs, figures and screenshots found in DIR (or given as files): first pictures (a chart of each row's
// median wall time with its interval, accuracy against time where the rows hold accuracy, the
// screenshots side by side, all inline SVG and images), then sortable tables behind a toggle (the page's
// own script, nothing fetched), images beside the rows they belong to, the environment the rows record
// and the commands that measure them again. The page is written by tools/report.py under Debian's
// /usr/bin/python3 (SHADOWBENCH_PYTHON overrides it); this command finds the script, checks the
// inputs and maps the outcome to bench's exit codes (core/Error.h): 2 for an input that does not
// exist or holds nothing to report (and the script's own wrong-input refusals: -o a device or a
// folder), 3 when the Python interpreter or the script is missing here, 1 when the page cannot be
// written (a full disk) or the script fails. The script's one-line message becomes bench's; the line
// naming what it skipped (special files, files over their bound) is passed on as a warning.
#include <string>
#include <vector>

namespace sb {

class ReportCommand {
public:
    /// argv[0] is "report". Returns the exit code (throws sb::Error with the code otherwise).
    static int main(int argc, char** argv);
    /// tools/report.py: next to an installed binary first (BIN/../share/shadowbench/tools/, where
    /// `cmake --install` puts tools/), then the run-time search roots of core/Paths.h (the build tree,
    /// the source tree). "" when none has it.
    static std::string findScript();
    /// The interpreter that runs the script: $SHADOWBENCH_PYTHON, else /usr/bin/python3 (Debian's,
    /// whatever python3 comes first on PATH).
    static std::string python();
};

} // namespace sb
