// The hard-case table (tests/hard/HardCases.h) on Vulkan: every row whose technique has a Vulkan form,
// rendered by lavapipe with the validation layer on and judged by the Vulkan harness's own accuracy
// evaluator: the reference is traced at the samples of a G-buffer Vulkan rasterised
// (reference/VulkanGBufferRenderer.h), and the stability measures' perturbed frames (camera shift, light
// turn, drift) are Vulkan frames too. The same bounds as GL hold. The stability bounds are judged on the
// first row of each technique: their perturbed frames (8 more frames, about half a row's time) run the
// evaluator's code that every API shares, and each technique's Vulkan form answers a shifted camera and
// a turned light in its first row as in the others; GL judges them on every row (HardCaseTest.cpp). Every
// light of a row's scene is judged, stability on light 0 (tests/hard/HardCaseBounds.h).
// A row that names a driver (a technique whose Vulkan form needs a capability only that driver's lavapipe
// offers) runs in a child process of this test on that driver (tests/SecondDriver.h); a failure there
// names the row and prints what the child's test printed.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "HardCaseBounds.h"
#include "HardCases.h"
#include "SecondDriver.h"
#include "TestSupport.h"
#include "VulkanFrame.h"
#include "bench/lib/harness/VulkanHarness.h"
#include "bench/lib/measure/AccuracyEvaluator.h"
#include "registry/TechniqueRegistry.h"

using namespace sb;

namespace {

std::vector<test::HardCase> vulkanRows() {
    std::vector<test::HardCase> rows;
    for (const test::HardCase& c : test::kHardCases)
        if (TechniqueRegistry::hasVulkan(TechniqueSpec::parse(c.technique).name)) rows.push_back(c);
    return rows;
}

/// Whether `c` is its technique's first row in the table (the row whose stability is judged on Vulkan).
bool firstOfItsTechnique(const test::HardCase& c) {
    const std::string technique = TechniqueSpec::parse(c.technique).name;
    for (const test::HardCase& row : test::kHardCases)
        if (TechniqueSpec::parse(row.technique).name == technique) return std::string(row.name) == c.name;
    return false;
}

class HardCasesVulkan : public ::testing::TestWithParam<test::HardCase> {};

TEST_P(HardCasesVulkan, BoundsHold) {
    const test::HardCase& c = GetParam();
    if (c.driver && !test::runsOnDriver(c.driver)) return test::runThisTestOnDriver(c.driver, c.name);
    RunConfig cfg = test::quickConfig(test::hardCaseScene(c), c.camera, c.size);
    test::VulkanFrame vulkan(cfg, c.technique);
    AccuracyEvaluator evaluator(vulkan.harness());
    const test::HardCaseStability stability =
        firstOfItsTechnique(c) ? test::HardCaseStability::Judged : test::HardCaseStability::NotJudged;
    test::expectHardCaseLights(c, evaluator, vulkan.technique(), vulkan.harness().scene().lights.size(),
                               stability, " (Vulkan)");
}

INSTANTIATE_TEST_SUITE_P(Table, HardCasesVulkan, ::testing::ValuesIn(vulkanRows()),
                         [](const auto& p) { return std::string(p.param.name); });

} // namespace
