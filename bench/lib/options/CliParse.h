#pragma once
// The one way every bench subcommand runs CLI11: --help prints and ends the command (exit code 0),
// a parse error becomes sb::Error(BadInput) naming the subcommand's help, an unknown option names the
// nearest known one. Under CliCatalog::describe() it records the app instead of parsing (CliCatalog.h).
#include <string>

#include <CLI/CLI.hpp>

namespace sb {

/// Returns -1 to go on, or the exit code when the command is finished (--help, a catalog's capture).
/// Defined out of line (CliParse.cpp): CLI::App's parser is instantiated in one object, not in each
/// subcommand's, which took a third of the bench program's compile time.
int parseCli(CLI::App& app, int argc, char** argv, const std::string& helpCommand);

} // namespace sb
