#pragma once
// `--driver NAME|PATH`, the one definition every command that renders registers (runs, accuracy,
// sweeps, bottleneck, figures, golden, ci, explain). BenchApp applies the option before any command
// parses its arguments (core/DriverTable.h: the process runs itself again on the driver's libraries);
// the command only accepts it, for --help and so that an option no command takes stays an error.
#include <string>

#include <CLI/CLI.hpp>

namespace sb {

struct DriverOption {
    /// Registers --driver on `app`; the value lands in `into` (BenchApp has already acted on it).
    static void add(CLI::App& app, std::string& into);
};

} // namespace sb
