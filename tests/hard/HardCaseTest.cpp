// The hard-case table on GL (tests/hard/HardCases.h): each row's technique on a scene where shadows are
// known to break, judged against the Embree reference for every light of the scene, stability included
// (light 0's, tests/hard/HardCaseBounds.h). Rows of techniques without a GL form, and rows of a form only
// Vulkan has (HardCase::vulkanOnly), run on Vulkan only (tests/hard/HardCaseVkTest.cpp); a row that names a
// driver runs in a child process on it (tests/SecondDriver.h).
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "HardCaseBounds.h"
#include "HardCases.h"
#include "SecondDriver.h"
#include "TestSupport.h"
#include "bench/lib/harness/Harness.h"
#include "bench/lib/measure/AccuracyEvaluator.h"
#include "registry/TechniqueRegistry.h"

using namespace sb;

namespace {

std::vector<test::HardCase> glRows() {
    std::vector<test::HardCase> rows;
    for (const test::HardCase& c : test::kHardCases)
        if (!c.vulkanOnly && TechniqueRegistry::has(TechniqueSpec::parse(c.technique).name, Api::GL))
            rows.push_back(c);
    return rows;
}

// No row is left out of both tests: its technique has a form on one API at least (an unknown or
// misspelt technique would otherwise drop the row without a word).
TEST(HardCaseTable, EveryRowRunsOnGlOrVulkan) {
    for (const test::HardCase& c : test::kHardCases) {
        const std::string technique = TechniqueSpec::parse(c.technique).name;
        EXPECT_TRUE(TechniqueRegistry::has(technique, Api::GL) ||
                    TechniqueRegistry::has(technique, Api::Vulkan))
            << c.name << ": " << technique << " has no form on either API";
        if (c.vulkanOnly)
            EXPECT_TRUE(TechniqueRegistry::has(technique, Api::Vulkan))
                << c.name << ": marked Vulkan only, but " << technique << " has no Vulkan form";
    }
}

class HardCases : public ::testing::TestWithParam<test::HardCase> {};

TEST_P(HardCases, BoundsHold) {
    const test::HardCase& c = GetParam();
    if (c.driver && !test::runsOnDriver(c.driver)) return test::runThisTestOnDriver(c.driver, c.name);
    const std::string scene = test::hardCaseScene(c);
    RunConfig cfg = test::quickConfig(scene, c.camera, c.size);
    Harness harness(cfg);
    auto technique = TechniqueRegistry::create(TechniqueSpec::parse(c.technique));
    harness.prepare(*technique);
    AccuracyEvaluator evaluator(harness);
    test::expectHardCaseLights(c, evaluator, *technique, harness.scene().lights.size(),
                               test::HardCaseStability::Judged);
}

INSTANTIATE_TEST_SUITE_P(Table, HardCases, ::testing::ValuesIn(glRows()),
                         [](const auto& p) { return std::string(p.param.name); });

} // namespace
