// The hard-case table (tests/hard/HardCases.h) on Vulkan: every row whose technique has a Vulkan form,
// rendered by lavapipe with the validation layer on and judged against the Embree reference of a GL
// harness of the same configuration (its G-buffer places the reference's samples; same size and camera,
// so the same pixels). The same bounds hold for error, error off the edge band, false shadow, negative
// controls and numeric sanity. The stability bounds (camera and light gains, flicker) are GL's alone:
// their perturbed frames are rendered by the GL harness (bench/lib/measure/AccuracyEvaluator.h), so on Vulkan
// they would measure GL again.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "HardCaseBounds.h"
#include "HardCases.h"
#include "TestSupport.h"
#include "VulkanFrame.h"
#include "bench/lib/harness/Harness.h"
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
    RunConfig gl = cfg;
    gl.api = RunConfig::Api::GL;
    Harness judge(gl);
    AccuracyEvaluator evaluator(judge);
    // Stability not judged: its perturbed frames would be GL's (the opening comment says why).
    const AccuracyResult r =
        evaluator.evaluateVisibility(vulkan.harness().targets().readVisibilityRGBA32F(),
                                     test::hardCaseOptions(c, test::HardCaseStability::NotJudged));
    test::expectHardCaseBounds(c, r, test::HardCaseStability::NotJudged, " (Vulkan)", evaluator.lastJudged());
}

INSTANTIATE_TEST_SUITE_P(Table, HardCasesVulkan, ::testing::ValuesIn(vulkanRows()),
                         [](const auto& p) { return std::string(p.param.name); });

} // namespace
