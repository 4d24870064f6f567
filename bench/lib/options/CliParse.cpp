#include "bench/lib/options/CliParse.h"

#include "bench/lib/options/CliCatalog.h"
#include "core/Error.h"

namespace sb {

int parseCli(CLI::App& app, int argc, char** argv, const std::string& helpCommand) {
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
