#pragma once
// The bounds of a hard-case row (tests/hard/HardCases.h) held against what the accuracy evaluator
// measured, written once for both APIs: tests/hard/HardCaseTest.cpp judges GL's frame,
// tests/hard/HardCaseVkTest.cpp Vulkan's. Each test renders and evaluates in its own way; the options
// of the evaluation, the line printed and every assertion come from here.
#include <cstdint>
#include <iostream>
#include <vector>

#include <gtest/gtest.h>

#include "HardCases.h"
#include "bench/lib/measure/AccuracyEvaluator.h"

namespace sb::test {

/// Whether a run is held to the row's stability bounds (camera gain, light gain, flicker).
enum class HardCaseStability {
    Judged,   ///< measured on the technique's own frames and held to the row's bounds
    NotJudged ///< not measured and not asserted; the caller says why where it passes this
};

/// The evaluator's options for row `c`: the row's n.L threshold, and the perturbed frames of the
/// stability measures only when `stability` is Judged (AccuracyOptions::stability).
inline AccuracyOptions hardCaseOptions(const HardCase& c, HardCaseStability stability) {
    AccuracyOptions options;
    options.nDotLThreshold = c.nDotL;
    if (stability == HardCaseStability::NotJudged) options.stability = false;
    return options;
}

/// Holds row `c`'s RMSE (r.soft) to that of drawing no shadow on the same judged samples of `judged`
/// (the evaluator's last frame: visibility 1 against its reference) plus the row's maxRmseOverNone.
inline void expectNoWorseThanNoShadow(const HardCase& c, const AccuracyResult& r,
                                      const AccuracyEvaluator::Sample* judged) {
    ASSERT_NE(judged, nullptr) << c.name << ": the RMSE bound needs the judged frame";
    const std::vector<float> lit(judged->reference.size(), 1.0f);
    const double none = AccuracyMetrics::soft(lit, judged->reference, judged->mask).rmse;
    std::cout << c.name << ": RMSE " << r.soft.rmse << ", no shadow's " << none << "\n";
    EXPECT_LE(r.soft.rmse, none + c.maxRmseOverNone) << c.why;
}

/// Prints one line of what `r` measured for row `c` (`api` after the row's name, e.g. " (Vulkan)"; the
/// stability measures only when Judged) and holds `r` to the row's bounds: more than 1/20 of the pixels
/// judged, no NaN, Inf or out-of-range value, error with and without the edge band, false shadow, the
/// negative controls' lower bound, the RMSE against no shadow's and against its own bound where the row asks
/// (`frame`: the evaluator's last frame) and, when `stability` is Judged, camera gain, light gain and
/// flicker. Every bound's failure carries the row's `why`. Non-fatal (EXPECT): a row reports every bound it
/// breaks.
inline void expectHardCaseBounds(const HardCase& c, const AccuracyResult& r, HardCaseStability stability,
                                 const char* api = "", const AccuracyEvaluator::Sample* frame = nullptr) {
    const bool judged = stability == HardCaseStability::Judged;
    std::cout << c.name << api << ": evaluated " << r.hard.evaluated << ", wrong " << r.hard.wrongPct
              << "% (no edge " << r.hard.wrongNoEdgePct << "%, false shadow " << r.hard.falseShadowPct
              << "%)";
    if (judged)
        std::cout << ", camera gain " << r.cameraGain << " (" << r.cameraChangesTechnique << "/"
                  << r.cameraChangesReference << "), light gain " << r.lightGain << " ("
                  << r.lightChangesTechnique << "/" << r.lightChangesReference << "), flicker " << r.flicker;
    std::cout << "\n";
    EXPECT_GT(r.hard.evaluated, uint64_t(c.size * c.size / 20)) << "too few judged pixels to mean anything";
    EXPECT_EQ(r.sanity.nan, 0u);
    EXPECT_EQ(r.sanity.inf, 0u);
    EXPECT_EQ(r.sanity.outOfRange, 0u);
    EXPECT_LE(r.hard.wrongPct, c.maxWrongPct) << c.why;
    EXPECT_LE(r.hard.wrongNoEdgePct, c.maxWrongNoEdgePct) << c.why;
    if (judged) {
        EXPECT_LE(r.cameraGain, c.maxCameraGain) << c.why;
        EXPECT_LE(r.lightGain, c.maxLightGain) << c.why;
        EXPECT_LE(r.flicker, c.maxFlicker) << c.why;
    }
    EXPECT_GE(r.hard.wrongNoEdgePct, c.minWrongNoEdgePct) << c.why;
    EXPECT_LE(r.hard.falseShadowPct, c.maxFalseShadowPct) << c.why;
    if (c.maxRmseOverNone >= 0.0) expectNoWorseThanNoShadow(c, r, frame);
    if (c.maxRmse >= 0.0) {
        std::cout << c.name << ": RMSE " << r.soft.rmse << "\n";
        EXPECT_LE(r.soft.rmse, c.maxRmse) << c.why;
    }
}

} // namespace sb::test
