// The hard-case table (tests/hard/HardCases.h) on Vulkan: every row whose technique has a Vulkan form,
// rendered by lavapipe with the validation layer on and judged against the Embree reference of a GL
// harness of the same configuration (its G-buffer places the reference's samples; same size and camera,
// so the same pixels). The same bounds hold for error, error off the edge band, false shadow, negative
// controls and numeric sanity. The stability bounds (camera and light gains, flicker) are GL's alone:
// their perturbed frames are rendered by the GL harness (bench/lib/measure/AccuracyEvaluator.h), so on Vulkan
// they would measure GL again.
#include <iostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "HardCases.h"
#include "TestSupport.h"
#include "VkTestSupport.h"
#include "bench/lib/measure/AccuracyEvaluator.h"
#include "bench/lib/harness/Harness.h"
#include "bench/lib/harness/VulkanHarness.h"
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
    cfg.api = RunConfig::Api::Vulkan;
    cfg.vulkan.validation = true;
    VulkanHarness vulkan(cfg);
    auto technique = TechniqueRegistry::createVulkan(TechniqueSpec::parse(c.technique));
    vulkan.prepare(*technique);
    vulkan.renderFrame(*technique);
    RunConfig gl = cfg;
    gl.api = RunConfig::Api::GL;
    Harness judge(gl);
    AccuracyEvaluator evaluator(judge);
    AccuracyOptions options;
    options.nDotLThreshold = c.nDotL;
    options.stability = false;
    const AccuracyResult r = evaluator.evaluateVisibility(vulkan.targets().readVisibilityRGBA32F(), options);
    std::cout << c.name << " (Vulkan): evaluated " << r.hard.evaluated << ", wrong " << r.hard.wrongPct
              << "% (no edge " << r.hard.wrongNoEdgePct << "%, false shadow " << r.hard.falseShadowPct
              << "%)\n";
    EXPECT_GT(r.hard.evaluated, uint64_t(c.size * c.size / 20)) << "too few judged pixels to mean anything";
    EXPECT_EQ(r.sanity.nan, 0u);
    EXPECT_EQ(r.sanity.inf, 0u);
    EXPECT_EQ(r.sanity.outOfRange, 0u);
    EXPECT_LE(r.hard.wrongPct, c.maxWrongPct) << c.why;
    EXPECT_LE(r.hard.wrongNoEdgePct, c.maxWrongNoEdgePct) << c.why;
    EXPECT_GE(r.hard.wrongNoEdgePct, c.minWrongNoEdgePct) << c.why;
    EXPECT_LE(r.hard.falseShadowPct, c.maxFalseShadowPct) << c.why;
    EXPECT_EQ(test::validationErrorLog(vulkan.context()), "");
    technique.reset();
}

INSTANTIATE_TEST_SUITE_P(Table, HardCasesVulkan, ::testing::ValuesIn(vulkanRows()),
                         [](const auto& p) { return std::string(p.param.name); });

} // namespace
