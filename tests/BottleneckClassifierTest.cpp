// BottleneckClassifier against hand-derived answers (no GL needed).
//
// Tolerances. solveNnls on exactly solvable systems: 1e-12 absolute; every expected value is O(1) and
// the solves are 2x2..3x3 eliminations on unit-diagonal normal matrices, so only the last bits can
// differ. classify on noise-free synthetic studies: 1e-9 on shares and coefficients; the normalised loads
// span 0.002 .. 2667, and the errors measured are ~1e-14, so 1e-9 leaves room for another compiler or
// FMA contraction while sitting far below the 0.04+ share gaps that separate one label from another.
// With +-3 % noise: shares within 0.1 of the truth; the worst of 40 draws per workload is 0.03..0.06
// (0.06 over 5000 draws), the immediate-mode workloads being the loosest because one run
// (submit_retained) alone separates the calls' cost from the vertices'.
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bench/lib/bottleneck/BottleneckClassifier.h"
#include "core/Error.h"

using sb::BottleneckClassifier;
using sb::BottleneckResult;
using sb::BottleneckRun;
using sb::StageLoads;
namespace pert = sb::perturbation;

namespace {

constexpr double kExact = 1e-12;
constexpr double kFitTol = 1e-9;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double residualSumOfSquares(const std::vector<double>& A, size_t m, size_t n, const std::vector<double>& b,
                            const std::vector<double>& x) {
    double ssr = 0;
    for (size_t r = 0; r < m; ++r) {
        double fit = 0;
        for (size_t j = 0; j < n; ++j) fit += A[r * n + j] * x[j];
        ssr += (fit - b[r]) * (fit - b[r]);
    }
    return ssr;
}

// ---------------------------------------------------------------------------------------------------
// solveNnls

TEST(BottleneckClassifierTest, NnlsRecoversExactSolution) {
    // x = (0.5, 2, 1.25) is positive, so the constrained and unconstrained optima coincide at b = A x:
    //   b0 = 0.5 + 2 + 0     = 2.5      b2 = 0 + 2 + 1.25        = 3.25
    //   b1 = 1 + 0 + 3.75    = 4.75     b3 = 1.5 + 4 + 0.3125    = 5.8125
    const std::vector<double> A = {1, 1, 0, //
                                   2, 0, 3, //
                                   0, 1, 1, //
                                   3, 2, 0.25};
    const std::vector<double> b = {2.5, 4.75, 3.25, 5.8125};
    std::vector<double> x = BottleneckClassifier::solveNnls(A, 4, 3, b);
    ASSERT_EQ(x.size(), 3u);
    const std::array<double, 3> expected = {0.5, 2.0, 1.25};
    for (size_t j = 0; j < 3; ++j) EXPECT_NEAR(x[j], expected[j], kExact) << "component " << j;
}

TEST(BottleneckClassifierTest, NnlsClampsNegativeComponentAtTheConstrainedOptimum) {
    // A = [1 0; 0 1; 1 1], b = (2, -1, 1).
    // Unconstrained: A^T A = [2 1; 1 2], A^T b = (3, 0); inverse (1/3)[2 -1; -1 2] gives x = (2, -1).
    // Constrained, x2 = 0: minimise (x1 - 2)^2 + 1 + (x1 - 1)^2 -> x1 = 1.5, SSR = 0.25 + 1 + 0.25 = 1.5.
    // Constrained, x1 = 0: minimise 4 + (x2 + 1)^2 + (x2 - 1)^2 -> x2 = 0, SSR = 6 (worse).
    // KKT at (1.5, 0): residual b - A x = (0.5, -1, -0.5), column 2 . residual = -1.5 <= 0, optimal.
    // Clipping the unconstrained answer to (2, 0) would give SSR = 0 + 1 + 1 = 2: not the optimum.
    const std::vector<double> A = {1, 0, 0, 1, 1, 1};
    const std::vector<double> b = {2, -1, 1};
    std::vector<double> x = BottleneckClassifier::solveNnls(A, 3, 2, b);
    ASSERT_EQ(x.size(), 2u);
    EXPECT_NEAR(x[0], 1.5, kExact);
    EXPECT_EQ(x[1], 0.0);
    EXPECT_NEAR(residualSumOfSquares(A, 3, 2, b, x), 1.5, kExact);
}

TEST(BottleneckClassifierTest, NnlsAllNegativeCorrelationGivesZero) {
    // A = (1, 1)^T, b = (-1, -2): any x > 0 moves A x further from b, so x = 0 (SSR = 1 + 4 = 5).
    std::vector<double> x = BottleneckClassifier::solveNnls({1, 1}, 2, 1, {-1, -2});
    ASSERT_EQ(x.size(), 1u);
    EXPECT_EQ(x[0], 0.0);
}

TEST(BottleneckClassifierTest, NnlsRankDeficientIsFeasibleAndMinimal) {
    // Column 2 = 2 * column 1, column 3 = 0. A x = (x1 + 2 x2) (1, 1, 1), best at the mean of b:
    // x1 + 2 x2 = (1 + 2 + 3) / 3 = 2, SSR = 1 + 0 + 1 = 2. Every subset with both column 1 and 2 or
    // with column 3 is singular; {1} and {2} tie, and the documented tie-break (fewest columns, then
    // lowest index) picks x = (2, 0, 0).
    const std::vector<double> A = {1, 2, 0, //
                                   1, 2, 0, //
                                   1, 2, 0};
    const std::vector<double> b = {1, 2, 3};
    std::vector<double> x = BottleneckClassifier::solveNnls(A, 3, 3, b);
    ASSERT_EQ(x.size(), 3u);
    for (size_t j = 0; j < 3; ++j) {
        EXPECT_TRUE(std::isfinite(x[j])) << "component " << j;
        EXPECT_GE(x[j], 0.0) << "component " << j;
    }
    EXPECT_NEAR(x[0] + 2 * x[1], 2.0, kExact);
    EXPECT_NEAR(residualSumOfSquares(A, 3, 3, b, x), 2.0, kExact);
    EXPECT_NEAR(x[0], 2.0, kExact);
    EXPECT_EQ(x[1], 0.0);
    EXPECT_EQ(x[2], 0.0);
}

TEST(BottleneckClassifierTest, NnlsFewerRowsThanColumns) {
    // One row (1, 1), b = 3: every x1 + x2 = 3 fits exactly; the single-column subset {1} comes first.
    std::vector<double> x = BottleneckClassifier::solveNnls({1, 1}, 1, 2, {3});
    ASSERT_EQ(x.size(), 2u);
    EXPECT_NEAR(x[0], 3.0, kExact);
    EXPECT_EQ(x[1], 0.0);
}

TEST(BottleneckClassifierTest, NnlsRejectsInconsistentArguments) {
    EXPECT_THROW(BottleneckClassifier::solveNnls({1, 2, 3}, 2, 2, {1, 2}), std::invalid_argument);
    EXPECT_THROW(BottleneckClassifier::solveNnls({1, 2}, 1, 2, {1, 2}), std::invalid_argument);
    EXPECT_THROW(BottleneckClassifier::solveNnls(std::vector<double>(7, 1.0), 1, 7, {1}),
                 std::invalid_argument);
    EXPECT_THROW(BottleneckClassifier::solveNnls({1, kNaN}, 2, 1, {1, 2}), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------------
// Synthetic studies: the aircraft scene's loads, times from known per-stage costs.

struct Perturbed {
    const char* name;
    StageLoads loads;
};

/// Loads of the nine perturbations. Retained baseline: C0 = 1200 calls, V0 = 1.6e6, F0 = 2.1e6.
/// Immediate mode issues 2 calls per vertex (position + normal), so C0 = 3.2e6 and C follows V under
/// tessellation. Ratios to the baseline, by hand: submit C 3.2e6 / 1200 = 8000/3 (or 1200 / 3.2e6 =
/// 3/8000), scale_x10_near F x9, scale_x0.01 F x0.002, size F x0.25 / x4, tess V x0.25 / x4 (F x0.98 /
/// x1.02), lp_no_rast F = 0.
std::vector<Perturbed> studyLoads(bool immediate) {
    const double c0 = immediate ? 3.2e6 : 1200, v0 = 1.6e6, f0 = 2.1e6;
    auto calls = [&](double vertices) { return immediate ? 2 * vertices : c0; };
    return {
        {pert::kBaseline, {c0, v0, f0}},
        {immediate ? pert::kSubmitRetained : pert::kSubmitImmediate, {immediate ? 1200 : 3.2e6, v0, f0}},
        {pert::kScaleNear, {c0, v0, 1.89e7}},
        {pert::kScaleSmall, {c0, v0, 4.2e3}},
        {pert::kSizeHalf, {c0, v0, 5.25e5}},
        {pert::kSizeDouble, {c0, v0, 8.4e6}},
        {pert::kTessHalf, {calls(4.0e5), 4.0e5, 2.058e6}},
        {pert::kTessDouble, {calls(6.4e6), 6.4e6, 2.142e6}},
        {pert::kNoRasterizer, {c0, v0, 0}},
    };
}

/// One workload: the milliseconds each term costs at the baseline, and the shares they imply by hand
/// (share = term / T0, shareCpu = (fixed + calls) / T0).
struct Workload {
    const char* name;
    bool immediate;
    double fixedMs, callsMs, vertexMs, fillMs;
    double shareCpu, shareVertex, shareFill, shareFixed;
    const char* label;
};

const Workload kWorkloads[] = {
    // T0 = 0.5 + 0.3 + 1.5 + 7.7 = 10
    {"fill", false, 0.5, 0.3, 1.5, 7.7, 0.08, 0.15, 0.77, 0.05, "fill"},
    // T0 = 0.4 + 0.2 + 6.0 + 1.4 = 8
    {"vertex", false, 0.4, 0.2, 6.0, 1.4, 0.075, 0.75, 0.175, 0.05, "vertex"},
    // T0 = 1 + 31 + 4 + 4 = 40; tess moves C and V together, submit_retained separates them
    {"cpu", true, 1.0, 31.0, 4.0, 4.0, 0.8, 0.1, 0.1, 0.025, "cpu"},
    // T0 = 1 + 1 + 3.5 + 4.5 = 10: no share reaches 0.5
    {"mixedFillVertex", false, 1.0, 1.0, 3.5, 4.5, 0.2, 0.35, 0.45, 0.1, "mixed:fill+vertex"},
    // T0 = 0.4 + 4 + 2.2 + 3.4 = 10, immediate
    {"mixedCpuFill", true, 0.4, 4.0, 2.2, 3.4, 0.44, 0.22, 0.34, 0.04, "mixed:cpu+fill"},
};

/// T = a + c C + v V + f F with c = callsMs / C0, v = vertexMs / V0, f = fillMs / F0.
std::vector<BottleneckRun> makeStudy(const Workload& w) {
    std::vector<Perturbed> loads = studyLoads(w.immediate);
    const StageLoads l0 = loads.front().loads;
    std::vector<BottleneckRun> runs;
    for (const Perturbed& p : loads) {
        double ms = w.fixedMs + w.callsMs / l0.cpu * p.loads.cpu + w.vertexMs / l0.vertex * p.loads.vertex +
                    w.fillMs / l0.fill * p.loads.fill;
        runs.push_back({p.name, ms, p.loads});
    }
    return runs;
}

/// Uniform in [-1, 1) from the raw mt19937 output, which the standard fixes bit for bit (the
/// std::uniform_real_distribution algorithm is not, so values could differ between libraries).
double symmetricUnit(std::mt19937& rng) {
    return 2.0 * (double(rng()) / 4294967296.0) - 1.0;
}

void expectShares(const BottleneckResult& r, const Workload& w, double tol) {
    EXPECT_NEAR(r.shareCpu, w.shareCpu, tol) << w.name;
    EXPECT_NEAR(r.shareVertex, w.shareVertex, tol) << w.name;
    EXPECT_NEAR(r.shareFill, w.shareFill, tol) << w.name;
    EXPECT_EQ(r.label, w.label) << w.name << ": shares cpu " << r.shareCpu << " vertex " << r.shareVertex
                                << " fill " << r.shareFill;
}

TEST(BottleneckClassifierTest, RecoversSharesOfNoiseFreeStudies) {
    for (const Workload& w : kWorkloads) {
        BottleneckResult r = BottleneckClassifier::classify(makeStudy(w));
        expectShares(r, w, kFitTol);
        EXPECT_NEAR(r.shareFixed, w.shareFixed, kFitTol) << w.name;
        EXPECT_NEAR(r.shareCpu + r.shareVertex + r.shareFill, 1.0, kExact) << w.name;
        // Normalised coefficients are the same fractions of T0 (each load ratio is 1 at the baseline).
        const double t0 = w.fixedMs + w.callsMs + w.vertexMs + w.fillMs;
        EXPECT_NEAR(r.coefFixed, w.fixedMs / t0, kFitTol) << w.name;
        EXPECT_NEAR(r.coefCpu, w.callsMs / t0, kFitTol) << w.name;
        EXPECT_NEAR(r.coefVertex, w.vertexMs / t0, kFitTol) << w.name;
        EXPECT_NEAR(r.coefFill, w.fillMs / t0, kFitTol) << w.name;
        EXPECT_NEAR(r.r2, 1.0, kFitTol) << w.name;
        EXPECT_LT(r.maxRelResidual, kFitTol) << w.name;
        EXPECT_FALSE(r.poorFit) << w.name;
        // Nine runs, the two scale runs held out (predicted, not fitted): exactly predicted here.
        EXPECT_EQ(r.runsInFit, 7u) << w.name;
        EXPECT_LT(r.heldOutRelError, kFitTol) << w.name;
    }
}

TEST(BottleneckClassifierTest, LabelsSurviveThreePercentNoise) {
    // Every frame time, the baseline's included, times 1 + u with u uniform in [-0.03, 0.03).
    constexpr double kNoise = 0.03, kShareTol = 0.1;
    constexpr int kDraws = 40;
    std::mt19937 rng(20240611u);
    for (const Workload& w : kWorkloads) {
        double worst = 0;
        for (int draw = 0; draw < kDraws; ++draw) {
            std::vector<BottleneckRun> runs = makeStudy(w);
            for (BottleneckRun& run : runs) run.wallMs *= 1.0 + kNoise * symmetricUnit(rng);
            BottleneckResult r = BottleneckClassifier::classify(runs);
            SCOPED_TRACE(std::string(w.name) + " draw " + std::to_string(draw));
            expectShares(r, w, kShareTol);
            EXPECT_FALSE(r.poorFit) << "r2 " << r.r2;
            worst = std::max({worst, std::abs(r.shareCpu - w.shareCpu),
                              std::abs(r.shareVertex - w.shareVertex), std::abs(r.shareFill - w.shareFill)});
        }
        RecordProperty(std::string("worstShareError_") + w.name, std::to_string(worst));
    }
}

TEST(BottleneckClassifierTest, EvidenceRatiosMatchHandComputation) {
    // Fill workload (a 0.5, calls 0.3, vertex 1.5, fill 7.7 ms at the baseline; T0 = 10 ms):
    //   submit_immediate  C x8000/3: 0.5 + 0.3 * 8000/3 + 1.5 + 7.7 = 809.7  -> 80.97
    //   scale_x10_near    F x9:      2.3 + 69.3                     = 71.6   -> 7.16
    //   scale_x0.01       F x0.002:  2.3 + 0.0154                   = 2.3154 -> 0.23154
    //   size_half         F x0.25:   2.3 + 1.925                    = 4.225  -> 0.4225
    //   size_double       F x4:      2.3 + 30.8                     = 33.1   -> 3.31
    //   tess_half         V x0.25, F x0.98: 0.8 + 0.375 + 7.546     = 8.721  -> 0.8721
    //   tess_double       V x4, F x1.02:    0.8 + 6 + 7.854         = 14.654 -> 1.4654
    //   lp_no_rast        F = 0:     0.5 + 0.3 + 1.5                = 2.3    -> 0.23
    struct Expected {
        const char* name;
        double time, cpu, vertex, fill;
    };
    const Expected expected[] = {
        {pert::kBaseline, 1.0, 1, 1, 1},          {pert::kSubmitImmediate, 80.97, 8000.0 / 3.0, 1, 1},
        {pert::kScaleNear, 7.16, 1, 1, 9},        {pert::kScaleSmall, 0.23154, 1, 1, 0.002},
        {pert::kSizeHalf, 0.4225, 1, 1, 0.25},    {pert::kSizeDouble, 3.31, 1, 1, 4},
        {pert::kTessHalf, 0.8721, 1, 0.25, 0.98}, {pert::kTessDouble, 1.4654, 1, 4, 1.02},
        {pert::kNoRasterizer, 0.23, 1, 1, 0},
    };
    BottleneckResult r = BottleneckClassifier::classify(makeStudy(kWorkloads[0]));
    ASSERT_EQ(r.evidence.size(), std::size(expected));
    auto near = [](double x, double y) { return std::abs(x - y) <= kExact * std::max(1.0, std::abs(y)); };
    for (size_t i = 0; i < std::size(expected); ++i) {
        const sb::RunEvidence& e = r.evidence[i];
        const Expected& x = expected[i];
        EXPECT_EQ(e.perturbation, x.name);
        EXPECT_TRUE(near(e.timeRatio, x.time))
            << x.name << ": T/T0 " << e.timeRatio << " expected " << x.time;
        EXPECT_TRUE(near(e.loadRatio.cpu, x.cpu)) << x.name << ": C/C0 " << e.loadRatio.cpu;
        EXPECT_TRUE(near(e.loadRatio.vertex, x.vertex)) << x.name << ": V/V0 " << e.loadRatio.vertex;
        EXPECT_TRUE(near(e.loadRatio.fill, x.fill)) << x.name << ": F/F0 " << e.loadRatio.fill;
        EXPECT_NEAR(e.fittedTimeRatio, x.time, kFitTol * std::max(1.0, x.time)) << x.name;
        const bool heldOut = BottleneckClassifier::isHeldOut(x.name);
        EXPECT_EQ(e.usedInFit, !heldOut) << x.name;
        EXPECT_EQ(e.heldOut, heldOut) << x.name;
    }
}

// ---------------------------------------------------------------------------------------------------
// Missing and degenerate inputs.

TEST(BottleneckClassifierTest, CollinearLoadsGoToTheEarlierStage) {
    // CPU workload (immediate) without submit_retained: C = 2 V in every run, so C/C0 = V/V0 exactly
    // (0.25 under tess_half, 4 under tess_double, 1 elsewhere) and the two columns are identical. Their
    // joint cost, calls 31 + vertex 4 ms of T0 = 40, goes to the earlier stage (cpu): shareCpu =
    // (1 + 35) / 40 = 0.9, shareVertex = 0; fill is still separated (0.1).
    const Workload& w = kWorkloads[2];
    std::vector<BottleneckRun> runs = makeStudy(w);
    ASSERT_EQ(runs[1].perturbation, pert::kSubmitRetained);
    runs.erase(runs.begin() + 1);
    BottleneckResult r = BottleneckClassifier::classify(runs);
    EXPECT_NEAR(r.shareCpu, 0.9, kFitTol);
    EXPECT_EQ(r.shareVertex, 0.0);
    EXPECT_NEAR(r.shareFill, 0.1, kFitTol);
    EXPECT_NEAR(r.shareFixed, 0.025, kFitTol);
    EXPECT_EQ(r.label, "cpu");
}

/// The runs of `runs` named in `names`, in the order of `runs`.
std::vector<BottleneckRun> only(const std::vector<BottleneckRun>& runs, std::vector<std::string> names) {
    std::vector<BottleneckRun> out;
    for (const BottleneckRun& r : runs)
        for (const std::string& n : names)
            if (r.perturbation == n) out.push_back(r);
    return out;
}

TEST(BottleneckClassifierTest, MissingRunsStillClassify) {
    // Fill workload, retained, 4 runs: C never moves, so the calls' 0.3 ms is indistinguishable from the
    // fixed 0.5 ms and goes to the fixed part (coefCpu = 0, shareFixed = shareCpu = 0.8 / 10). The
    // other 3 unknowns are fitted exactly from 4 exact points, so shares stay 0.08 / 0.15 / 0.77.
    const Workload& w = kWorkloads[0];
    BottleneckResult r = BottleneckClassifier::classify(
        only(makeStudy(w), {pert::kBaseline, pert::kSizeHalf, pert::kSizeDouble, pert::kTessHalf}));
    expectShares(r, w, kFitTol);
    EXPECT_NEAR(r.shareFixed, 0.08, kFitTol);
    EXPECT_EQ(r.coefCpu, 0.0);
    EXPECT_EQ(r.runsInFit, 4u);
    EXPECT_EQ(r.evidence.size(), 4u);
}

TEST(BottleneckClassifierTest, FailedRunIsLeftOutButReported) {
    // Five runs, one failed (NaN time): the fit uses the other four; the failed one keeps its load ratios
    // (size_double F x4) and prediction (fill workload: 0.8 + 1.5 + 7.7 * 4 = 33.1 ms -> 3.31) in the
    // evidence, with T/T0 NaN and usedInFit false.
    const Workload& w = kWorkloads[0];
    std::vector<BottleneckRun> runs = only(makeStudy(w), {pert::kBaseline, pert::kSizeHalf, pert::kSizeDouble,
                                                          pert::kTessHalf, pert::kTessDouble});
    ASSERT_EQ(runs[2].perturbation, pert::kSizeDouble); // study order
    runs[2].wallMs = kNaN;
    BottleneckResult r = BottleneckClassifier::classify(runs);
    expectShares(r, w, kFitTol);
    EXPECT_EQ(r.runsInFit, 4u);
    ASSERT_EQ(r.evidence.size(), 5u);
    const sb::RunEvidence& failed = r.evidence[2];
    EXPECT_EQ(failed.perturbation, pert::kSizeDouble);
    EXPECT_FALSE(failed.usedInFit);
    EXPECT_TRUE(std::isnan(failed.timeRatio));
    EXPECT_NEAR(failed.loadRatio.fill, 4.0, kExact);
    EXPECT_NEAR(failed.fittedTimeRatio, 3.31, kFitTol);
    for (size_t i : {0u, 1u, 3u, 4u}) EXPECT_TRUE(r.evidence[i].usedInFit) << r.evidence[i].perturbation;
}

/// Runs `runs` through classify, which must throw sb::Error(BadInput); returns its message.
std::string classifyError(const std::vector<BottleneckRun>& runs) {
    try {
        BottleneckClassifier::classify(runs);
    } catch (const sb::Error& e) {
        EXPECT_EQ(e.code(), sb::ExitCode::BadInput);
        return e.what();
    }
    ADD_FAILURE() << "classify did not throw";
    return {};
}

TEST(BottleneckClassifierTest, MissingBaselineThrowsNamingIt) {
    std::vector<BottleneckRun> runs = makeStudy(kWorkloads[0]);
    runs.erase(runs.begin()); // the baseline
    std::string message = classifyError(runs);
    EXPECT_NE(message.find("\"baseline\""), std::string::npos) << message;
    EXPECT_NE(message.find(pert::kSizeHalf), std::string::npos) << "lists what was given: " << message;

    std::vector<BottleneckRun> failed = makeStudy(kWorkloads[0]);
    failed[0].wallMs = 0;
    message = classifyError(failed);
    EXPECT_NE(message.find("\"baseline\" run has no finite positive frame time"), std::string::npos)
        << message;

    std::vector<BottleneckRun> twice = makeStudy(kWorkloads[0]);
    twice.push_back(twice[0]);
    message = classifyError(twice);
    EXPECT_NE(message.find("2 \"baseline\" runs"), std::string::npos) << message;
}

TEST(BottleneckClassifierTest, TooFewRunsThrowsNamingThem) {
    std::vector<BottleneckRun> runs = only(
        makeStudy(kWorkloads[0]), {pert::kBaseline, pert::kSizeHalf, pert::kTessHalf, pert::kSizeDouble});
    ASSERT_EQ(runs[2].perturbation, pert::kSizeDouble); // study order
    runs[2].loads.vertex = -1;                          // unusable load: 3 usable runs remain
    std::string message = classifyError(runs);
    EXPECT_NE(message.find("at least 4 runs"), std::string::npos) << message;
    EXPECT_NE(message.find("got 3 (baseline, size_half, tess_half)"), std::string::npos) << message;
}

TEST(BottleneckClassifierTest, ZeroBaselineFillGivesZeroFillShare) {
    // A technique without fragment work: F0 = 0, so F is left out of the fit. size_double still reports
    // F = 5 (cannot be normalised: ratio NaN, ignored by the fit). Costs: fixed 0.4, calls 0.6, vertex
    // 3.0 ms -> T0 = 4: shareCpu = 1 / 4 = 0.25, shareVertex = 0.75, shareFixed = 0.1, shareFill = 0.
    const Workload w = {"noFill", false, 0.4, 0.6, 3.0, 0.0, 0.25, 0.75, 0.0, 0.1, "vertex"};
    std::vector<BottleneckRun> runs;
    for (const Perturbed& p : studyLoads(false)) {
        StageLoads l = p.loads;
        l.fill = std::string(p.name) == pert::kSizeDouble ? 5 : 0;
        double ms = w.fixedMs + w.callsMs * l.cpu / 1200 + w.vertexMs * l.vertex / 1.6e6;
        runs.push_back({p.name, ms, l});
    }
    BottleneckResult r = BottleneckClassifier::classify(runs);
    expectShares(r, w, kFitTol);
    EXPECT_EQ(r.shareFill, 0.0);
    EXPECT_EQ(r.coefFill, 0.0);
    EXPECT_NEAR(r.shareFixed, w.shareFixed, kFitTol);
    for (const sb::RunEvidence& e : r.evidence) {
        EXPECT_TRUE(std::isnan(e.loadRatio.fill)) << e.perturbation;
        EXPECT_TRUE(std::isfinite(e.fittedTimeRatio)) << e.perturbation;
    }
    EXPECT_TRUE(std::isfinite(r.r2));
}

TEST(BottleneckClassifierTest, TimesAgainstTheLoadsArePoorFit) {
    // Frame time falls as fill rises (t = 1, 2, 0.5, 1.5 for F ratios 1, 0.25, 4, 0.002), C and V never
    // move: no non-negative model can follow, the fit is the constant mean t = 1.25 (KKT: the fill
    // column . residual = -0.25 + 0.25 * 0.75 - 4 * 0.75 + 0.002 * 0.25 < 0). SS_res = SS_tot, so
    // R^2 = 0; residuals relative to max(t, 1): 0.25/1, 0.75/2, 0.75/1, 0.25/1.5 -> max 0.75.
    // All of t0 is fixed: cpu.
    std::vector<BottleneckRun> runs = {
        {pert::kBaseline, 10, {1200, 1.6e6, 2.1e6}},
        {pert::kSizeHalf, 20, {1200, 1.6e6, 5.25e5}},
        {pert::kSizeDouble, 5, {1200, 1.6e6, 8.4e6}},
        {pert::kNoRasterizer, 15, {1200, 1.6e6, 4.2e3}},
    };
    BottleneckResult r = BottleneckClassifier::classify(runs);
    EXPECT_NEAR(r.r2, 0.0, kExact);
    EXPECT_TRUE(r.poorFit);
    EXPECT_NEAR(r.maxRelResidual, 0.75, kExact);
    // rms of 0.25, 0.375, 0.75, 1/6: sqrt((0.0625 + 0.140625 + 0.5625 + 0.027778) / 4) = 0.445366.
    EXPECT_NEAR(r.rmsRelResidual, 0.445366, 1e-6);
    EXPECT_NEAR(r.coefFixed, 1.25, kExact);
    EXPECT_NEAR(r.shareCpu, 1.0, kExact);
    EXPECT_EQ(r.shareFill, 0.0);
    EXPECT_EQ(r.label, "cpu");
}

TEST(BottleneckClassifierTest, FlatCpuBoundTimesAreAGoodFit) {
    // Nothing the study does moves the frame (+-2% noise written out): a CPU-bound frame. R^2 is
    // meaningless here (SS_tot is the noise), but the constant model is within 2% of every run, so the
    // fit is not poor: rms relative residual = rms(|t - mean| / t) with mean t = 1.0 exactly:
    // residuals relative to max(t, 1): 0, 0.02/1.02, 0.02/1, 0.01/1.01, 0.01/1 -> rms 0.01406.
    std::vector<BottleneckRun> runs = {
        {pert::kBaseline, 10.0, {1.6e5, 6e4, 7e4}},    {pert::kSizeHalf, 10.2, {1.6e5, 6e4, 1.7e4}},
        {pert::kSizeDouble, 9.8, {1.6e5, 6e4, 2.8e5}}, {pert::kTessHalf, 10.1, {1.6e5, 6e4, 7e4}},
        {pert::kTessDouble, 9.9, {1.6e5, 6e4, 7e4}},
    };
    BottleneckResult r = BottleneckClassifier::classify(runs);
    EXPECT_EQ(r.label, "cpu");
    EXPECT_FALSE(r.poorFit) << "rms relative residual " << r.rmsRelResidual;
    EXPECT_LT(r.rmsRelResidual, 0.02);
    EXPECT_GT(r.shareCpu, 0.9);
}

} // namespace
