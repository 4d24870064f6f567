// The workflow templates users copy (tools/ci/github-workflow.yml, tools/ci/gitlab-ci.yml) must call
// the script the project's own CI runs (scripts/test.sh runs scripts/gate.sh, and .ci/run runs
// scripts/test.sh), so a template cannot drift into a gate nobody runs. The YAML is parsed by a real
// parser (PyYAML, with /usr/bin/python3 as the plots use), not searched as text.
#include <gtest/gtest.h>

#include "TestSupport.h"

using namespace sb;

namespace {

/// Every shell command of a workflow file: GitHub's steps[].run, GitLab's script / before_script.
test::CommandResult commands(const std::string& file) {
    const std::string py = R"(
import sys, yaml
doc = yaml.safe_load(open(sys.argv[1]))
out = []
def walk(node):
    if isinstance(node, dict):
        for k, v in node.items():
            if k == 'run' and isinstance(v, str): out.append(v)
            elif k in ('script', 'before_script') and isinstance(v, list): out.extend(v)
            else: walk(v)
    elif isinstance(node, list):
        for v in node: walk(v)
walk(doc)
print('\n'.join(out))
)";
    test::writeFile("/tmp/shadowbench-workflow-commands.py", py);
    return test::runCommand("/usr/bin/python3 /tmp/shadowbench-workflow-commands.py " +
                            std::string(SB_SOURCE_DIR) + "/" + file);
}

TEST(CiWorkflowTest, TemplatesCallTheScriptTheProjectsCiRuns) {
    for (const char* file : {"tools/ci/github-workflow.yml", "tools/ci/gitlab-ci.yml"}) {
        SCOPED_TRACE(file);
        const auto r = commands(file);
        ASSERT_EQ(r.exitCode, 0) << r.output;
        EXPECT_NE(r.output.find("bash scripts/gate.sh"), std::string::npos) << r.output;
    }
    const std::string testScript = test::readFile(std::string(SB_SOURCE_DIR) + "/scripts/test.sh");
    EXPECT_NE(testScript.find("scripts/gate.sh\""), std::string::npos);
    EXPECT_NE(test::readFile(std::string(SB_SOURCE_DIR) + "/.ci/run").find("bash scripts/test.sh"),
              std::string::npos);
    const auto syntax = test::runCommand("bash -n " + std::string(SB_SOURCE_DIR) + "/scripts/gate.sh");
    EXPECT_EQ(syntax.exitCode, 0) << syntax.output;
}

TEST(CiWorkflowTest, BrokenYamlIsNoticed) {
    // The negative control of the parser above: a template that is not YAML must fail, not pass empty.
    const std::string dir = test::freshTestDir("workflow");
    test::writeFile(dir + "/bad.yml", "jobs: [unclosed\n");
    const std::string rel = std::filesystem::relative(dir + "/bad.yml", SB_SOURCE_DIR).string();
    EXPECT_NE(commands(rel).exitCode, 0);
}

} // namespace
