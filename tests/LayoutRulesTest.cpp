// The layout's dependency rules (tests/LayoutRules.h, docs/ARCHITECTURE.md "Layout") hold for the
// source tree, and the check is shown to bite: on a committed miniature tree with one breach of each
// rule it must report exactly the breaches listed beside it, no more (its allowed includes stay quiet,
// a Vulkan form whose includes reach no GL among them) and no fewer, so the check cannot pass by
// checking nothing. The Vulkan rule follows includes through headers: a Vulkan file that includes a
// neutral header which includes a GL one is a breach too.
#include <gtest/gtest.h>

#include "LayoutRules.h"
#include "TestPaths.h"

using namespace sb;

namespace {

const layout::fs::path kRoot = SB_SOURCE_DIR;
const std::string kFixture = "tests/data/layout_fixture";

std::string listed(const std::vector<layout::Violation>& violations) {
    std::string out;
    for (const auto& v : violations) out += "  " + v.text() + "\n";
    return out;
}

} // namespace

TEST(LayoutRulesTest, TheSourceTreeKeepsEveryRule) {
    // The fixture breaks the rules on purpose; the checker and its test name the patterns they look for.
    const auto violations =
        layout::check(kRoot, {kFixture, "tests/LayoutRules.h", "tests/LayoutRulesTest.cpp"});
    EXPECT_TRUE(violations.empty()) << violations.size() << " breaches of the layout rules:\n"
                                    << listed(violations);
    // The scan saw the tree: the layers it checks exist (a wrong root would find nothing to break).
    size_t cpp = 0;
    for (const auto& file : layout::detail::listFiles(kRoot, {kFixture}))
        cpp += layout::detail::isCpp(file) && !layout::detail::startsWith(file, "tests/") ? 1 : 0;
    EXPECT_GT(cpp, 150u) << "the checker found too few C++ files under " << kRoot;
}

TEST(LayoutRulesTest, TheFixtureBreachesAreAllFoundAndNothingElse) {
    const layout::fs::path fixture = kRoot / kFixture;
    std::vector<std::string> expected;
    for (const std::string& line : layout::detail::readLines(fixture / "EXPECTED"))
        if (!line.empty()) expected.push_back(line);
    ASSERT_GE(expected.size(), 10u) << "EXPECTED lists one breach of each rule";
    std::vector<std::string> found;
    for (const auto& v : layout::check(fixture)) found.push_back(v.key());
    EXPECT_EQ(found, expected) << "reported:\n" << listed(layout::check(fixture));
    // Every rule kind is exercised by the fixture.
    std::set<std::string> rules;
    for (const auto& v : layout::check(fixture)) rules.insert(v.rule);
    EXPECT_EQ(rules, (std::set<std::string>{"include", "vulkan-gl", "core-system", "shader", "shader-include",
                                            "outside-reference", "no-layer"}));
}
