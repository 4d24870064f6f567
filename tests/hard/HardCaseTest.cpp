// The hard-case table on GL (tests/hard/HardCases.h): each row's technique on a scene where shadows are
// known to break, judged against the Embree reference, stability included.
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "HardCases.h"
#include "TestSupport.h"
#include "bench/lib/measure/AccuracyEvaluator.h"
#include "bench/lib/harness/Harness.h"
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
    AccuracyOptions options;
    options.nDotLThreshold = c.nDotL;
    AccuracyResult r = evaluator.evaluate(*technique, options);
    std::cout << c.name << ": evaluated " << r.hard.evaluated << ", wrong " << r.hard.wrongPct
              << "% (no edge " << r.hard.wrongNoEdgePct << "%, false shadow " << r.hard.falseShadowPct
              << "%), camera gain " << r.cameraGain << " (" << r.cameraChangesTechnique << "/"
              << r.cameraChangesReference << "), light gain " << r.lightGain << " ("
              << r.lightChangesTechnique << "/" << r.lightChangesReference << "), flicker " << r.flicker
              << "\n";
    EXPECT_GT(r.hard.evaluated, uint64_t(c.size * c.size / 20)) << "too few judged pixels to mean anything";
    EXPECT_EQ(r.sanity.nan, 0u);
    EXPECT_EQ(r.sanity.inf, 0u);
    EXPECT_EQ(r.sanity.outOfRange, 0u);
    EXPECT_LE(r.hard.wrongPct, c.maxWrongPct) << c.why;
    EXPECT_LE(r.hard.wrongNoEdgePct, c.maxWrongNoEdgePct) << c.why;
    EXPECT_LE(r.cameraGain, c.maxCameraGain) << c.why;
    EXPECT_LE(r.lightGain, c.maxLightGain) << c.why;
    EXPECT_LE(r.flicker, c.maxFlicker) << c.why;
    EXPECT_GE(r.hard.wrongNoEdgePct, c.minWrongNoEdgePct) << c.why;
    EXPECT_LE(r.hard.falseShadowPct, c.maxFalseShadowPct) << c.why;
}

INSTANTIATE_TEST_SUITE_P(Table, HardCases, ::testing::ValuesIn(test::kHardCases),
                         [](const auto& p) { return std::string(p.param.name); });

} // namespace
