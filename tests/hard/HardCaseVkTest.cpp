// The hard-case table (tests/hard/HardCases.h) on Vulkan: every row whose technique has a Vulkan form,
// rendered by lavapipe with the validation layer on and judged by the Vulkan harness's own accuracy
// evaluator: the reference is traced at the samples of a G-buffer Vulkan rasterised
// (reference/VulkanGBufferRenderer.h), and the stability measures' perturbed frames (camera shift, light
// turn, drift) are Vulkan frames too. The same bounds as GL hold, stability included.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "HardCaseBounds.h"
#include "HardCases.h"
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

class HardCasesVulkan : public ::testing::TestWithParam<test::HardCase> {};

TEST_P(HardCasesVulkan, BoundsHold) {
    const test::HardCase& c = GetParam();
    RunConfig cfg = test::quickConfig(test::hardCaseScene(c), c.camera, c.size);
    test::VulkanFrame vulkan(cfg, c.technique);
    AccuracyEvaluator evaluator(vulkan.harness());
    const AccuracyResult r =
        evaluator.evaluate(vulkan.technique(), test::hardCaseOptions(c, test::HardCaseStability::Judged));
    EXPECT_TRUE(r.stabilityMeasured);
    test::expectHardCaseBounds(c, r, test::HardCaseStability::Judged, " (Vulkan)", evaluator.lastJudged());
}

INSTANTIATE_TEST_SUITE_P(Table, HardCasesVulkan, ::testing::ValuesIn(vulkanRows()),
                         [](const auto& p) { return std::string(p.param.name); });

} // namespace
