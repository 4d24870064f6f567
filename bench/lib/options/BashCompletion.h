#pragma once
// The bash completion of `bench`, written from the same tables as --help (CliCatalog.h) and the
// registry: subcommands, each subcommand's options, technique names after -t/--technique, a
// technique's property keys after "-t NAME:", scene names after --scene, the fixed values of the options
// that have them (--api, --submit, --format ...), file names elsewhere. `bench --completion bash` prints
// it; cmake/ManAndCompletion.cmake installs it as share/bash-completion/completions/bench.
#include <string>
#include <vector>

#include "bench/lib/options/CliCatalog.h"

namespace sb {

class BashCompletion {
public:
    /// The script: defines _bench and registers it with `complete -F _bench bench`. `commands[0]` is
    /// the plain run.
    static std::string render(const std::vector<CliCommand>& commands);
};

} // namespace sb
