// The bash completion as bash runs it: `bench --completion bash` is sourced in a real bash, _bench is
// called with COMP_WORDS and COMP_CWORD set as bash sets them, and COMPREPLY is held against independent
// answers: the registry's technique and property names, the built-in scenes on disk, the options
// `bench golden --help` prints.
#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "CliHelpOptions.h"
#include "TestSupport.h"
#include "registry/TechniqueRegistry.h"
#include "scenes/SceneLoader.h"

namespace {

class CompletionCli : public ::testing::Test {
protected:
    void SetUp() override {
        mDir = sb::test::freshTestDir("completion");
        mScript = mDir + "/bench.bash";
        const auto r = sb::test::runCommand(std::string(SB_BENCH_BINARY) + " --completion bash > " + mScript);
        ASSERT_EQ(r.exitCode, 0) << r.output;
    }

    /// COMPREPLY for the command line `words`, the last being the word under the cursor. `line`, when
    /// given, is COMP_LINE as bash sets it (then `words` are split at ':' as bash splits them). Runs in
    /// the scratch folder, so file names come from there.
    std::set<std::string> complete(const std::vector<std::string>& words, const std::string& line = "") {
        std::string script = "cd '" + mDir + "' && source '" + mScript + "' && COMP_WORDS=(";
        for (const std::string& w : words) script += "'" + w + "' ";
        script += ") && COMP_CWORD=" + std::to_string(words.size() - 1);
        if (!line.empty())
            script += " && COMP_LINE='" + line + "' && COMP_POINT=" + std::to_string(line.size());
        script += " && _bench && printf '%s\\n' \"${COMPREPLY[@]}\"\n";
        sb::test::writeFile(mDir + "/driver.sh", script);
        const auto r = sb::test::runCommand("bash " + mDir + "/driver.sh");
        EXPECT_EQ(r.exitCode, 0) << r.output;
        std::set<std::string> out;
        std::istringstream lines(r.output);
        for (std::string l; std::getline(lines, l);)
            if (!l.empty()) out.insert(l);
        return out;
    }

    std::string mDir, mScript;
};

std::set<std::string> withPrefix(const std::vector<std::string>& names, const std::string& prefix) {
    std::set<std::string> out;
    for (const std::string& n : names)
        if (n.rfind(prefix, 0) == 0) out.insert(n);
    return out;
}

std::vector<std::string> propertyNames(const std::string& technique) {
    std::vector<std::string> out;
    const auto created = sb::TechniqueRegistry::create(technique); // owns the info read below
    for (const sb::PropertyDesc& p : created->info().properties) out.push_back(p.name);
    return out;
}

} // namespace

TEST_F(CompletionCli, SubcommandsAndTheirOptions) {
    EXPECT_EQ(complete({"bench", "gol"}), (std::set<std::string>{"golden"}));
    EXPECT_EQ(complete({"bench", "--sce"}), (std::set<std::string>{"--scene"}));
    const auto help = sb::test::runCommand(std::string(SB_BENCH_BINARY) + " golden --help");
    std::set<std::string> longOptions;
    for (const std::string& o : sb::test::helpOptionNames(help.output))
        if (o.rfind("--", 0) == 0) longOptions.insert(o);
    ASSERT_GE(longOptions.size(), 5u) << help.output; // --help --check --update --scene --technique ...
    EXPECT_EQ(complete({"bench", "golden", "--"}), longOptions);
}

TEST_F(CompletionCli, TechniquesScenesAndProperties) {
    const std::vector<std::string> techniques = sb::TechniqueRegistry::names();
    EXPECT_EQ(complete({"bench", "-t", "shadowm"}), withPrefix(techniques, "shadowm"));
    EXPECT_EQ(complete({"bench", "--technique", ""}), withPrefix(techniques, ""));
    EXPECT_EQ(complete({"bench", "--scene", "te"}), withPrefix(sb::SceneLoader::listBuiltinScenes(), "te"));
    ASSERT_FALSE(withPrefix(sb::SceneLoader::listBuiltinScenes(), "te").empty());

    std::set<std::string> expected;
    for (const std::string& p : withPrefix(propertyNames("shadowmap"), "res"))
        expected.insert("shadowmap:" + p + "=");
    ASSERT_FALSE(expected.empty());
    EXPECT_EQ(complete({"bench", "-t", "shadowmap:res"}), expected);
    // A second property after a first one keeps the first.
    expected.clear();
    for (const std::string& p : withPrefix(propertyNames("shadowmap"), "p"))
        expected.insert("shadowmap:resolution=512:" + p + "=");
    EXPECT_EQ(complete({"bench", "-t", "shadowmap:resolution=512:p"}), expected);
}

TEST_F(CompletionCli, ColonSplitByBashCompletesTheTailOnly) {
    // Bash splits "shadowmap:res" at ':' (COMP_WORDBREAKS); readline then replaces only "res".
    std::set<std::string> expected;
    for (const std::string& p : withPrefix(propertyNames("shadowmap"), "res")) expected.insert(p + "=");
    EXPECT_EQ(complete({"bench", "-t", "shadowmap", ":", "res"}, "bench -t shadowmap:res"), expected);
}

TEST_F(CompletionCli, FixedValuesAndFileNames) {
    EXPECT_EQ(complete({"bench", "--api", ""}), (std::set<std::string>{"gl", "vulkan"}));
    EXPECT_EQ(complete({"bench", "--submit", "imm"}), (std::set<std::string>{"immediate"}));
    sb::test::writeFile(mDir + "/rows.csv", "a\n1\n");
    EXPECT_EQ(complete({"bench", "--csv", "ro"}), (std::set<std::string>{"rows.csv"}));
    EXPECT_EQ(complete({"bench", "export", "ro"}), (std::set<std::string>{"rows.csv"}));
}
