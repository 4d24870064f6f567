// A missing input file is wrong input in every subcommand that reads one: exit 2 (README "Exit codes"),
// and the one line on stderr names the path, before anything is measured. Each row is a subcommand and
// the option or argument through which it reads a file, given a path that does not exist.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "TestSupport.h"

namespace {

struct MissingInput {
    const char* name;
    std::string args; ///< "{missing}" stands for the nonexistent path
};

const std::vector<MissingInput> kCases = {
    {"merge input", "merge -o {dir}/out.csv {missing}"},
    {"export input", "export {missing}"},
    {"compare base", "compare {missing} {missing}"},
    {"report input", "report {missing}"},
    {"sweep definition", "sweep {missing} --dry-run"},
    {"run scene file", "--scene {missing} --frames 1"},
    {"run model file", "--model {missing} --frames 1"},
    {"accuracy scene file", "accuracy --scene {missing} --frames 1"},
    {"explain scene file", "explain --scene {missing}"},
    {"bottleneck rows", "bottleneck --from {missing}"},
    {"figures catalog", "figures --catalog {missing} --list"},
    {"ci suite", "ci --quick --suite {missing} --out {dir}/ci"},
    {"ci baseline", "ci --quick --baseline {missing} --out {dir}/ci"},
    {"ci base bench", "ci --quick --base-bench {missing} --out {dir}/ci"},
    {"golden folder", "golden --check --dir {missing} --scene teapot --technique none"},
};

std::string substituted(std::string text, const std::string& key, const std::string& value) {
    for (size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + value.size()))
        text.replace(at, key.size(), value);
    return text;
}

} // namespace

TEST(MissingInputCli, EverySubcommandExitsTwoNamingThePath) {
    const std::string dir = sb::test::freshTestDir("missing-input");
    for (const MissingInput& c : kCases) {
        SCOPED_TRACE(c.name);
        // A distinct path per case, so the message is known to name this one.
        const std::string missing = dir + "/no-such-" + std::to_string(&c - kCases.data()) + ".json";
        const std::string args = substituted(substituted(c.args, "{missing}", missing), "{dir}", dir);
        const sb::test::CommandResult r = sb::test::runCommand(std::string(SB_BENCH_BINARY) + " " + args);
        EXPECT_EQ(r.exitCode, 2) << r.output;
        EXPECT_NE(r.output.find(missing), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("bench: error: "), std::string::npos) << r.output;
    }
}
