#include "bench/report/ReportCommand.h"

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include <unistd.h>

#include "bench/lib/options/CliParse.h"
#include "bench/lib/sweep/ChildProcess.h"
#include "core/Error.h"
#include "core/Paths.h"

namespace sb {

namespace {

namespace fs = std::filesystem;

constexpr const char* kScript = "tools/report.py";

struct ReportCli {
    std::vector<std::string> inputs;
    std::string out, title;
    bool embed = false;
};

/// The default page: report.html in the first folder given (or in the first file's folder).
std::string defaultOut(const std::string& first) {
    const fs::path p(first);
    return ((fs::is_directory(p) ? p : p.parent_path()) / "report.html").string();
}

/// The lines of `text`, empty ones and trailing blanks left out.
std::vector<std::string> nonEmptyLines(const std::string& text) {
    std::vector<std::string> out;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(start, end - start);
        while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
        if (!line.empty()) out.push_back(line);
        start = end + 1;
    }
    return out;
}

/// tools/report.py says what it skipped, and why it failed, in lines of its own ("report.py: ...").
constexpr const char* kScriptPrefix = "report.py: ";

std::string withoutScriptPrefix(const std::string& line) {
    return line.rfind(kScriptPrefix, 0) == 0 ? line.substr(std::string(kScriptPrefix).size()) : line;
}

/// The error for a failed script: its own one-line message with its code where it gave one (2 wrong
/// input, 1 an OS failure such as a full disk), else how it ended and its last line (a bug).
Error scriptFailure(const ChildExit& exit) {
    const std::vector<std::string> lines = nonEmptyLines(exit.stderrTail);
    const std::string last = lines.empty() ? "" : lines.back();
    const bool ownMessage = exit.signal == 0 && (exit.exitCode == 1 || exit.exitCode == 2) &&
                            lines.size() == 1 && last.rfind(kScriptPrefix, 0) == 0;
    if (ownMessage)
        return Error("bench report: " + withoutScriptPrefix(last),
                     exit.exitCode == 2 ? ExitCode::BadInput : ExitCode::Failure);
    return Error("bench report: tools/report.py failed (" + exit.describe() + "): " + last,
                 ExitCode::Failure);
}

} // namespace

std::string ReportCommand::python() {
    const char* p = std::getenv("SHADOWBENCH_PYTHON");
    return p && *p ? p : "/usr/bin/python3";
}

std::string ReportCommand::findScript() {
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const fs::path installed = exe.parent_path().parent_path() / "share" / "shadowbench" / kScript;
        if (fs::is_regular_file(installed, ec)) return installed.string();
    }
    return Paths::findResource(kScript);
}

int ReportCommand::main(int argc, char** argv) {
    CLI::App app{"bench report: one static HTML page from result CSVs, figures and images", "bench report"};
    app.footer(R"(Examples:
  bench -t none -t shadowmap --frames 10 --csv out/run.csv --screenshot out/shot.png
  bench report out                           out/report.html: time per row (and accuracy against time
                                             where measured), the screenshots, the table behind a toggle
  bench report results/figures -o /tmp/figures.html   every figure with its rows
  bench report run.csv shot_none.png --embed -o page.html   images inside the page (one file to send)
  xdg-open out/report.html                   sort by clicking a heading; works from file://, no server

Folders are searched recursively for *.csv, images (*.png, *.svg, *.jpg) and README.md (whose command
lines are listed as the way to reproduce). The page is written by tools/report.py with /usr/bin/python3
(SHADOWBENCH_PYTHON overrides). Only regular files are read, each within a size bound; what is skipped
(a FIFO, a link to a device, a file over its bound) is listed in the page and in one line on stderr.
The page is written through PAGE.partial (created exclusively, fsynced, renamed over the page).
Exit codes: 2 an input is missing or not a file or folder, -o names a device, FIFO or folder, or the
inputs hold no CSV or image; 3 no Python interpreter or no tools/report.py here; 1 the page cannot
be written (a full disk: the old page is kept) or the script failed.)");
    ReportCli cli;
    app.add_option("inputs", cli.inputs, "folders, result CSVs, images, README.md")->required();
    app.add_option("-o,--out", cli.out, "the page to write (default: FIRST_FOLDER/report.html)");
    app.add_option("--title", cli.title, "the page's title (default: from the inputs' names)");
    app.add_flag("--embed", cli.embed, "write the images into the page as data: URLs (a single file)");
    if (int code = parseCli(app, argc, argv, "bench report"); code >= 0) return code;

    std::error_code ec;
    for (const std::string& input : cli.inputs)
        if (!fs::exists(input, ec))
            throw Error("bench report: '" + input +
                            "' does not exist (a folder of results, a CSV or an image)",
                        ExitCode::BadInput);
    const std::string interpreter = python();
    if (access(interpreter.c_str(), X_OK) != 0)
        throw Error("bench report: " + interpreter +
                        " is missing: the page is written by tools/report.py under Debian's python3 "
                        "(apt-get install python3, or set SHADOWBENCH_PYTHON)",
                    ExitCode::Unsupported);
    const std::string script = findScript();
    if (script.empty())
        throw Error("bench report: cannot find tools/report.py (looked in ../share/shadowbench/ next to the "
                    "binary, the build tree and the source tree)",
                    ExitCode::Unsupported);

    std::vector<std::string> command{interpreter, script};
    command.insert(command.end(), cli.inputs.begin(), cli.inputs.end());
    command.insert(command.end(), {"--out", cli.out.empty() ? defaultOut(cli.inputs.front()) : cli.out});
    if (!cli.title.empty()) command.insert(command.end(), {"--title", cli.title});
    if (cli.embed) command.push_back("--embed");
    const ChildExit exit =
        ChildProcess::run(command, {}, [](const std::string& line) { std::cout << line << "\n"; });
    if (!exit.ok()) throw scriptFailure(exit);
    // A page written all the same: what it left out (special files, files over their bound, names
    // that cannot be linked safely) is one line, also listed in the page.
    for (const std::string& line : nonEmptyLines(exit.stderrTail))
        std::cerr << "bench: warning: bench report: " << withoutScriptPrefix(line) << "\n";
    return 0;
}

} // namespace sb
