// `bench bisect`'s bad input, which must be refused before anything is built: exit 2 (the input is
// wrong) with one line naming what was wrong. The repository is this source tree; nothing here builds
// or checks out a commit (the search itself: tests/BisectSearchTest.cpp; the whole path:
// scripts/bisect-proof.sh, results/bisect/README.md).
#include <string>

#include <gtest/gtest.h>

#include "TestSupport.h"

using namespace sb;

namespace {

struct BadBisect {
    const char* name;
    std::string args;
    std::string mustContain;
};

/// The case's name in gtest's messages instead of its bytes.
void PrintTo(const BadBisect& c, std::ostream* os) {
    *os << c.name;
}

class BisectCli : public ::testing::TestWithParam<BadBisect> {};

} // namespace

TEST_P(BisectCli, RefusesWithExitTwoAndOneLine) {
    const BadBisect& c = GetParam();
    const std::string src = test::shellQuoted(test::sourceDir());
    const auto r = test::runCommand(std::string(test::benchBinary()) + " bisect " + c.args + " --repo " +
                                    src + " --suite " + src + "/results/ci/suite.json");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find(c.mustContain), std::string::npos) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << "one line:\n" << r.output;
}

// GOOD/BAD are resolved in the source tree, whose history has a root commit and HEAD; HEAD~1 may not
// exist in a shallow clone, so the order case uses the root commit.
INSTANTIATE_TEST_SUITE_P(
    BadInput, BisectCli,
    ::testing::Values(BadBisect{"unknown_commit", "no-such-commit-0f3e HEAD -c none_aircraft",
                                "unknown commit 'no-such-commit-0f3e'"},
                      BadBisect{"good_not_ancestor",
                                "HEAD $(git -C " + test::shellQuoted(test::sourceDir()) +
                                    " rev-list --max-parents=0 HEAD | head -1) -c none_aircraft",
                                "is not an ancestor"},
                      BadBisect{"same_commit", "HEAD HEAD -c none_aircraft", "same commit"},
                      BadBisect{"no_such_config",
                                "$(git -C " + test::shellQuoted(test::sourceDir()) +
                                    " rev-list --max-parents=0 HEAD | head -1) HEAD -c no_such_config",
                                "no configuration 'no_such_config'"}),
    [](const ::testing::TestParamInfo<BadBisect>& p) { return std::string(p.param.name); });
