#pragma once
// The options of one measured run (`bench [options]`, `bench accuracy [options]`) into a RunConfig.
// Every subcommand that measures parses its run options here, so `bench sweep`, `bench bottleneck`,
// the sweep's worker processes and handloop accept exactly what `bench` accepts.
#include <string>
#include <utility>
#include <vector>

#include "bench/lib/options/RunConfig.h"

namespace sb {

class RunOptions {
public:
    /// Parses arguments into `config` (argv[0] is the program name). Returns -1 to continue, or an exit
    /// code when the command is finished (--help, a parse error; --list sets `listOnly` and returns -1).
    /// `footer` ends --help (the dispatcher's subcommands and examples). Throws sb::Error for bad values.
    /// `imagesDir`, when given, takes `--images DIR` (bench accuracy's pictures,
    /// bench/lib/images/AccuracyImages.h; refused outside `bench accuracy`); without it the option does not
    /// exist (the sweep's workers, explain and handloop draw no such pictures).
    static int parse(int argc, char** argv, RunConfig& config, bool& listOnly, const std::string& footer = {},
                     std::string* imagesDir = nullptr);
    /// parse() over a list of options (no program name): the sweep checks and the worker use it.
    static RunConfig parseArgs(const std::vector<std::string>& args, RunConfig::Mode mode);
    /// For the commands that render with GL only (explain, sweep and what stands on it, handloop): throws
    /// sb::Error(Unsupported) naming `command` when `config` asks for --api vulkan, so it never runs GL
    /// while the user asked for Vulkan.
    static void requireGl(const RunConfig& config, const std::string& command);
    /// "1024x768" -> (1024, 768); throws sb::Error naming the option.
    static std::pair<int, int> parseSize(const std::string& text);
};

} // namespace sb
