#pragma once
// The one way every bench subcommand runs CLI11: --help prints and ends the command (exit code 0),
// a parse error becomes sb::Error(BadInput) naming the subcommand's help, an unknown option names the
// nearest known one. Under CliCatalog::describe() it records the app instead of parsing (CliCatalog.h).
#include <string>

#include <CLI/CLI.hpp>

#include "bench/lib/options/CliCatalog.h"
#include "core/Error.h"

namespace sb {

/// Returns -1 to go on, or the exit code when the command is finished (--help, a catalog's capture).
inline int parseCli(CLI::App& app, int argc, char** argv, const std::string& helpCommand) {
    if (CliCatalog::capture(app)) return 0;
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ExtrasError&) {
        throw Error(CliCatalog::unexpected(app) + " (see " + helpCommand + " --help)");
    } catch (const CLI::ParseError& e) {
        throw Error(std::string(e.what()) + " (see " + helpCommand + " --help)");
    }
    return -1;
}

} // namespace sb
