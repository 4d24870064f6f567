// The hard-case table on GL (tests/hard/HardCases.h): each row's technique on a scene where shadows are
// known to break, judged against the Embree reference, stability included.
#include <string>

#include <gtest/gtest.h>

#include "HardCaseBounds.h"
#include "HardCases.h"
#include "TestSupport.h"
#include "bench/lib/harness/Harness.h"
#include "bench/lib/measure/AccuracyEvaluator.h"
#include "registry/TechniqueRegistry.h"

using namespace sb;

namespace {

class HardCases : public ::testing::TestWithParam<test::HardCase> {};

TEST_P(HardCases, BoundsHold) {
    const test::HardCase& c = GetParam();
    const std::string scene = test::hardCaseScene(c);
    RunConfig cfg = test::quickConfig(scene, c.camera, c.size);
    Harness harness(cfg);
    auto technique = TechniqueRegistry::create(TechniqueSpec::parse(c.technique));
    harness.prepare(*technique);
    AccuracyEvaluator evaluator(harness);
    const AccuracyResult r =
        evaluator.evaluate(*technique, test::hardCaseOptions(c, test::HardCaseStability::Judged));
    test::expectHardCaseBounds(c, r, test::HardCaseStability::Judged, "", evaluator.lastJudged());
}

INSTANTIATE_TEST_SUITE_P(Table, HardCases, ::testing::ValuesIn(test::kHardCases),
                         [](const auto& p) { return std::string(p.param.name); });

} // namespace
