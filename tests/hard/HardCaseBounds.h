#pragma once
// The bounds of a hard-case row (tests/hard/HardCases.h) held against what the accuracy evaluator
// measured, written once for both APIs: tests/hard/HardCaseTest.cpp judges GL's frame,
// tests/hard/HardCaseVkTest.cpp Vulkan's. Each test renders in its own way; the evaluation of every light
// of the row's scene, its options, the lines printed and every assertion come from here.
#include <algorithm>
#include <cstdint>
#include <iostream>
#include <string>
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

/// Prints one line of what `r` measured for row `c` (`label` after the row's name, e.g. " (Vulkan)" or
/// " (Vulkan) light 1"; the stability measures only when Judged) and holds `r` to the row's bounds: more
/// than 1/20 of the pixels judged, no NaN, Inf or out-of-range value, error with and without the edge
/// band, false shadow, the RMSE against no shadow's and against its own bound where the row asks
/// (`frame`: the evaluator's last frame) and, when `stability` is Judged, camera gain, light gain and
/// flicker. Every bound's failure carries the row's `why`. Non-fatal (EXPECT): a row reports every bound it
/// breaks. The negative controls' lower bound is the caller's (expectHardCaseLights: the worst light's).
inline void expectHardCaseBounds(const HardCase& c, const AccuracyResult& r, HardCaseStability stability,
                                 const std::string& label = "",
                                 const AccuracyEvaluator::Sample* frame = nullptr) {
    const bool judged = stability == HardCaseStability::Judged;
    std::cout << c.name << label << ": evaluated " << r.hard.evaluated << ", wrong " << r.hard.wrongPct
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
    EXPECT_LE(r.hard.falseShadowPct, c.maxFalseShadowPct) << c.why;
    if (c.maxRmseOverNone >= 0.0) expectNoWorseThanNoShadow(c, r, frame);
    if (c.maxRmse >= 0.0) {
        std::cout << c.name << ": RMSE " << r.soft.rmse << "\n";
        EXPECT_LE(r.soft.rmse, c.maxRmse) << c.why;
    }
}

/// Judges row `c` for every light of its scene, `lights` of them (the harness's scene), with
/// `technique` prepared on `evaluator`'s harness: each light's frame rendered and traced against the
/// reference on its own (AccuracyOptions::light), each held to the row's bounds by expectHardCaseBounds,
/// so the bounds apply to the worst light, and a failure names the light (a scene of one light prints
/// and fails as before: `api` alone after the row's name). The stability measures (`stability`) are
/// light 0's alone: they judge how the technique's image answers a shifted camera, a turned light and a
/// drift, which one light shows, and each further light would cost their 8 frames again. A negative
/// control's lower bound (minWrongNoEdgePct) holds for the worst light: the harness must see the error
/// on one light at least.
inline void expectHardCaseLights(const HardCase& c, AccuracyEvaluator& evaluator, Technique& technique,
                                 size_t lights, HardCaseStability stability, const std::string& api = "") {
    ASSERT_GT(lights, 0u) << c.name << ": the scene has no light to judge";
    double worstNoEdgePct = 0.0;
    for (size_t light = 0; light < lights; ++light) {
        const std::string label = lights > 1 ? api + " light " + std::to_string(light) : api;
        SCOPED_TRACE(c.name + label);
        const HardCaseStability own = light == 0 ? stability : HardCaseStability::NotJudged;
        AccuracyOptions options = hardCaseOptions(c, own);
        options.light = int(light);
        const AccuracyResult r = evaluator.evaluate(technique, options);
        EXPECT_EQ(r.stabilityMeasured, own == HardCaseStability::Judged);
        expectHardCaseBounds(c, r, own, label, evaluator.lastJudged());
        worstNoEdgePct = std::max(worstNoEdgePct, r.hard.wrongNoEdgePct);
    }
    EXPECT_GE(worstNoEdgePct, c.minWrongNoEdgePct) << c.why;
}

} // namespace sb::test
