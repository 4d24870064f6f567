// The lookups of `msm` and `evsm` (shaders/shadowmap/msm.glsl, evsm.glsl) and vsm's beside them, evaluated by
// the shaders themselves on lavapipe (a compute fixture, tests/shaders/vk/moment_bounds.comp) on moments of
// depth distributions the test states, against answers in closed form:
//   - one depth d: the region's fraction in front of t is 0 for t < d and 1 for t > d; the Hamburger
//     reconstruction gives it to the moment bias's error away from the step, on the float and the unorm16
//     map, and so does EVSM (its variance is 0);
//   - two depths (Peters and Klein 2015, Moment Shadow Mapping: four moments pin down a distribution of two
//     depths): msm gives the true fraction where vsm's Chebyshev bound leaks (a receiver close behind the
//     farther depth: 4/13 lit where the truth is 0), and EVSM's bound is Chebyshev's in the warped space,
//     here worked out in double from the distribution;
//   - the maps' "no occluder" values the C++ clears a layer to (Msm::noOccluder, Evsm::noOccluder) are what
//     the depth pass would write for depth 1, and the paper's quantisation keeps every depth's moments in
//     [0, 1] (what the unorm16 map can hold).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "TestSupport.h"
#include "VkComputeKernel.h"
#include "VkTestSupport.h"
#include "techniques/PropertySet.h"
#include "techniques/shadowmap/Evsm.h"
#include "techniques/shadowmap/Msm.h"
#include "vk/VulkanBuffer.h"

namespace sb {
namespace {

using test::VulkanTest;

/// moment_bounds.comp's Case and modes.
struct GpuCase {
    glm::vec4 moments{0.0f};
    glm::vec4 params{0.0f}; ///< t, bias or minVariance, bleed reduction, mode
    glm::vec4 exponents{0.0f};
};
static_assert(sizeof(GpuCase) == 48);
enum Mode { MsmFloat = 0, MsmUnorm16 = 1, Evsm2 = 2, Evsm4 = 3, Quantize = 4, EvsmMoments = 5, Vsm = 6 };
constexpr uint32_t kLocalSize = 64; ///< moment_bounds.comp's local_size_x

/// A distribution of depths: (depth, weight) pairs, weights summing to 1.
using Depths = std::vector<std::pair<double, double>>;

/// E[f(d)] over `depths`.
template <class F>
double expectation(const Depths& depths, F f) {
    double sum = 0.0;
    for (const auto& [d, w] : depths) sum += w * f(d);
    return sum;
}

glm::vec4 powerMoments(const Depths& depths) {
    return glm::vec4(float(expectation(depths, [](double d) { return d; })),
                     float(expectation(depths, [](double d) { return d * d; })),
                     float(expectation(depths, [](double d) { return d * d * d; })),
                     float(expectation(depths, [](double d) { return d * d * d * d; })));
}

/// The moments of the two warps exp(c+ d) and -exp(-c- d) (Lauritzen and McCool 2008).
glm::vec4 warpedMoments(const Depths& depths, double cp, double cn) {
    const auto wp = [cp](double d) { return std::exp(cp * d); };
    const auto wn = [cn](double d) { return -std::exp(-cn * d); };
    return glm::vec4(
        float(expectation(depths, wp)), float(expectation(depths, [&](double d) { return wp(d) * wp(d); })),
        float(expectation(depths, wn)), float(expectation(depths, [&](double d) { return wn(d) * wn(d); })));
}

/// The fraction of `depths` strictly in front of t: what every map estimates.
double inFront(const Depths& depths, double t) {
    return expectation(depths, [t](double d) { return d < t ? 1.0 : 0.0; });
}

/// Chebyshev's one-tailed bound on the fraction at or behind t for the warp w (an increasing function), in
/// double: the textbook form sigma^2 / (sigma^2 + (w(t) - mu)^2), 1 for w(t) <= mu.
template <class W>
double chebyshev(const Depths& depths, double t, W w) {
    const double mu = expectation(depths, w);
    const double variance = expectation(depths, [&](double d) { return (w(d) - mu) * (w(d) - mu); });
    const double x = w(t) - mu;
    return x <= 0.0 ? 1.0 : variance / (variance + x * x);
}

class MsmEvsmVkTest : public VulkanTest {
protected:
    std::vector<glm::vec4> evaluate(const std::vector<GpuCase>& cases) {
        namespace fs = std::filesystem;
        const fs::path root = test::freshTestDir("moment_bounds");
        fs::create_directory_symlink(fs::path(SB_SOURCE_DIR) / "shaders" / "shadowmap", root / "shadowmap");
        fs::create_directory_symlink(fs::path(SB_SOURCE_DIR) / "tests" / "shaders" / "vk", root / "test");
        test::ComputeKernel kernel(context(), "test/moment_bounds.comp", {}, 2, sizeof(uint32_t),
                                   "moment bounds test", root.string());
        VulkanBuffer in(context(), cases.size() * sizeof(GpuCase), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        VulkanBuffer out(context(), cases.size() * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        std::copy(cases.begin(), cases.end(), static_cast<GpuCase*>(in.map()));
        const uint32_t count = uint32_t(cases.size());
        kernel.dispatch({&in, &out}, &count, (count + kLocalSize - 1) / kLocalSize);
        const auto* data = static_cast<const glm::vec4*>(out.map());
        return std::vector<glm::vec4>(data, data + cases.size());
    }
};

/// The default moment bias (Msm's `moment_bias`, the paper's alpha for the 64-bit map).
constexpr float kBias = 3e-5f;

// The bias pulls the moments towards those of half a unit of mass at 0 and half at 1 (the moments
// (0.5, 0.5, 0.5, 0.5)), weight alpha, so the reconstruction answers for that slightly wider distribution:
// its error grows as the receiver nears a depth of the region. Worked out in float arithmetic on the CPU
// for these cases when writing the test: 0.0012 at 0.05 behind one depth, 0.0135 at 0.05 behind the
// farther of two depths 0.2 apart, 0.0102 halfway between them; the unorm16 map's rounding (1/65535 per
// stored value) moved none of them by more than 1e-4. Bound: 0.02.
constexpr double kMsmTolerance = 0.02;

TEST_F(MsmEvsmVkTest, MsmOneDepthIsAStepAwayFromIt) {
    const Depths one = {{0.3, 1.0}};
    const double ts[] = {0.05, 0.2, 0.25, 0.35, 0.5, 0.9, 1.0};
    std::vector<GpuCase> cases;
    for (const Mode mode : {MsmFloat, MsmUnorm16})
        for (const double t : ts) cases.push_back({powerMoments(one), {float(t), kBias, 0.0f, float(mode)}});
    const std::vector<glm::vec4> gpu = evaluate(cases);
    for (size_t i = 0; i < cases.size(); ++i) {
        const double t = cases[i].params.x;
        EXPECT_NEAR(gpu[i].x, inFront(one, t), kMsmTolerance)
            << "mode " << cases[i].params.w << ", depth 0.3, receiver at " << t;
    }
}

TEST_F(MsmEvsmVkTest, MsmTwoDepthsAreExactWhereVsmLeaks) {
    // Half the region at 0.3, half at 0.5 (two occluders). VSM's moments: mu = 0.4, sigma^2 = 0.01.
    // A receiver at t = 0.55, just behind the farther occluder, is fully shadowed; Chebyshev's bound
    // reads 0.01 / (0.01 + 0.15^2) = 4/13 lit (the light leak). At t = 0.4 (between them, truth half
    // lit) the bound reads 1 (t <= mu). Four moments determine this distribution: msm answers 1 and 0.5
    // in front (visibility 0 and 0.5).
    const Depths two = {{0.3, 0.5}, {0.5, 0.5}};
    const glm::vec4 b = powerMoments(two);
    const double ts[] = {0.2, 0.4, 0.55, 0.8};
    std::vector<GpuCase> cases;
    for (const double t : ts) {
        cases.push_back({b, {float(t), kBias, 0.0f, float(MsmFloat)}});
        cases.push_back({b, {float(t), kBias, 0.0f, float(MsmUnorm16)}});
        cases.push_back({b, {float(t), 0.0f, 0.0f, float(Vsm)}});
    }
    const std::vector<glm::vec4> gpu = evaluate(cases);
    for (size_t i = 0; i < cases.size(); i += 3) {
        const double t = cases[i].params.x;
        EXPECT_NEAR(gpu[i].x, inFront(two, t), kMsmTolerance) << "msm float, receiver at " << t;
        EXPECT_NEAR(gpu[i + 1].x, inFront(two, t), kMsmTolerance) << "msm unorm16, receiver at " << t;
    }
    // vsm's bound at 0.55 and 0.4, the hand-computed leak (float moments: 1e-5).
    EXPECT_NEAR(gpu[2 * 3 + 2].x, 4.0 / 13.0, 1e-5);
    EXPECT_NEAR(gpu[1 * 3 + 2].x, 1.0, 1e-6);
}

TEST_F(MsmEvsmVkTest, EvsmIsChebyshevInTheWarpedSpaces) {
    // The same two occluders and one depth; the paper's 32-bit exponents (40, 5) and a pair that makes
    // the negative warp the tighter bound (5, 40). Expected: Chebyshev's bound of each warp in double, the
    // smaller of the two for components=4; minimum variance and bleed reduction 0.
    const Depths two = {{0.3, 0.5}, {0.5, 0.5}};
    const Depths one = {{0.3, 1.0}};
    const glm::vec2 exponents[] = {{40.0f, 5.0f}, {5.0f, 40.0f}};
    const double ts[] = {0.2, 0.4, 0.55, 0.8};
    std::vector<GpuCase> cases;
    std::vector<double> expected;
    for (const Depths* depths : {&two, &one})
        for (const glm::vec2 c : exponents)
            for (const double t : ts)
                for (const Mode mode : {Evsm2, Evsm4}) {
                    const double cp = c.x, cn = c.y;
                    const double positive =
                        chebyshev(*depths, t, [cp](double d) { return std::exp(cp * d); });
                    const double negative =
                        chebyshev(*depths, t, [cn](double d) { return -std::exp(-cn * d); });
                    cases.push_back({warpedMoments(*depths, cp, cn),
                                     {float(t), 0.0f, 0.0f, float(mode)},
                                     glm::vec4(c, 0.0f, 0.0f)});
                    expected.push_back(mode == Evsm2 ? positive : std::min(positive, negative));
                }
    const std::vector<glm::vec4> gpu = evaluate(cases);
    for (size_t i = 0; i < cases.size(); ++i) {
        // The moments are floats of values up to exp(2 * 40 * 0.5) = 2.4e17: relative error 6e-8 each, and
        // sigma^2 = M2 - M1^2 loses what the two share; 1e-3 absolute covers that cancellation for these
        // distributions (their variances are at least 1/4 of M1^2).
        EXPECT_NEAR(gpu[i].x, expected[i], 1e-3)
            << "mode " << cases[i].params.w << ", exponents " << cases[i].exponents.x << ","
            << cases[i].exponents.y << ", receiver at " << cases[i].params.x;
    }
    // The leak, closed form: at t = 0.55 behind both occluders vsm reads 4/13 = 0.31 lit; evsm with c+ = 40:
    // sigma^2 / (sigma^2 + (e^22 - mu)^2) with mu = (e^12 + e^20) / 2 and sigma = (e^20 - e^12) / 2: 0.0052.
    const double mu = (std::exp(12.0) + std::exp(20.0)) / 2, sigma = (std::exp(20.0) - std::exp(12.0)) / 2;
    const double leak = sigma * sigma / (sigma * sigma + (std::exp(22.0) - mu) * (std::exp(22.0) - mu));
    EXPECT_NEAR(gpu[2 * 2].x, leak, 1e-4);
    EXPECT_LT(leak, 0.006);
    // One depth (variance 0 up to rounding): shadowed behind it, lit in front, for both warps.
    for (size_t i = 16; i < cases.size(); ++i)
        EXPECT_NEAR(gpu[i].x, 1.0 - inFront(one, cases[i].params.x), 1e-3);
}

TEST_F(MsmEvsmVkTest, ClearValuesAreTheMomentsOfDepthOne) {
    PropertySet msm("msm", Msm::declaration().properties);
    PropertySet evsm("evsm", Evsm::declaration().properties);
    evsm.set(Evsm::kExponentPositive, "42");
    evsm.set(Evsm::kExponentNegative, "7");
    std::vector<GpuCase> cases = {{{}, {1.0f, 0.0f, 0.0f, float(Quantize)}},
                                  {{}, {1.0f, 0.0f, 0.0f, float(EvsmMoments)}, {42.0f, 7.0f, 0.0f, 0.0f}}};
    // The paper's transform keeps every depth's moments in [0, 1]: what a unorm16 texel holds.
    for (int k = 0; k <= 100; ++k) cases.push_back({{}, {float(k) / 100, 0.0f, 0.0f, float(Quantize)}});
    const std::vector<glm::vec4> gpu = evaluate(cases);
    const glm::vec4 quantized = Msm::noOccluder(msm);
    // Float sums of four terms up to 82 (an ulp of 82 is 7.6e-6): 3e-5, two unorm16 steps.
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(gpu[0][c], quantized[c], 3e-5) << "component " << c;
    const glm::vec4 warped = Evsm::noOccluder(evsm);
    // exp() on lavapipe and in libm, each within a few ulps: 1e-5 relative.
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(gpu[1][c] / warped[c], 1.0, 1e-5) << "component " << c;
    for (size_t i = 2; i < cases.size(); ++i)
        for (int c = 0; c < 4; ++c) {
            EXPECT_GE(gpu[i][c], -3e-5f) << "depth " << cases[i].params.x << ", component " << c;
            EXPECT_LE(gpu[i][c], 1.0f + 3e-5f) << "depth " << cases[i].params.x << ", component " << c;
        }
    msm.set(Msm::kFormat, "float");
    EXPECT_EQ(Msm::noOccluder(msm), glm::vec4(1.0f));
}

} // namespace
} // namespace sb
