// A mistyped name gets one line naming the nearest valid one and exit 2, at each of the five places a
// name is looked up: options, subcommands, techniques, technique properties and scenes. The expected
// suggestions are written by hand: each typo is one edit from the name it should suggest.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "TestSupport.h"

namespace {

struct Typo {
    std::string args;
    std::string line; ///< what stderr must contain
};

const std::vector<Typo> kTypos = {
    {"--instanses 5",
     "bench: error: unknown option --instanses (did you mean --instances?) (see bench --help)"},
    {"golden --chek", "unknown option --chek (did you mean --check?) (see bench golden --help)"},
    {"merge -o x.csv --forse a.csv", "unknown option --forse (did you mean --force?)"},
    {"golde", "bench: error: unknown subcommand golde (did you mean golden?) (see bench --help)"},
    {"swep -t none", "unknown subcommand swep (did you mean sweep?)"},
    {"-t shadowmapp --frames 1", "unknown technique 'shadowmapp' (did you mean shadowmap?)"},
    {"-t shadowmap:resolutoin=512 --frames 1", "unknown property 'resolutoin' (did you mean resolution?)"},
    {"--scene teapt --frames 1", "unknown scene 'teapt' (did you mean teapot?)"},
    {"golden --check --scene teapt", "--scene teapt: not a built-in scene (did you mean teapot?)"},
};

} // namespace

TEST(UnknownNameCli, EachTypoNamesTheNearestNameAndExitsTwo) {
    for (const Typo& t : kTypos) {
        SCOPED_TRACE(t.args);
        const sb::test::CommandResult r = sb::test::runCommand(std::string(SB_BENCH_BINARY) + " " + t.args);
        EXPECT_EQ(r.exitCode, 2) << r.output;
        EXPECT_NE(r.output.find(t.line), std::string::npos) << r.output;
    }
}

TEST(UnknownNameCli, AWordFarFromEverySubcommandSuggestsNothing) {
    const sb::test::CommandResult r = sb::test::runCommand(std::string(SB_BENCH_BINARY) + " xyzzy");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("bench: error: unknown subcommand xyzzy (see bench --help)"), std::string::npos)
        << r.output;
}
