// `-t auto`'s choice (bench/lib/select/AutoSelection.h) over hand-made candidate tables: it never picks a
// candidate that lacks a requested effect, misses the accuracy bound or was refused, and among the rest
// it picks the lowest measured cost, so changing the costs changes the choice (a fixed ranking fails
// that test); where the calibration's interleaved rounds cannot separate two candidates, the exact
// work decides (the last test). The effect masks are the ones the techniques declare (their headers), written
// out here.
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bench/lib/select/AutoSelection.h"

using namespace sb;

namespace {

constexpr EffectMask kHard = uint32_t(Effect::HardShadows);
constexpr EffectMask kSelf = Effect::HardShadows | Effect::SelfShadowing;
constexpr EffectMask kSoft = uint32_t(Effect::SoftShadows);
constexpr EffectMask kBleed = Effect::SoftShadows | Effect::ColourBleeding;

AutoCandidate candidate(const std::string& name, EffectMask effects, double ms, double wrong) {
    AutoCandidate c;
    c.spec = name + ":k=v";
    c.effects = effects;
    c.measured = true;
    c.costMs = ms;
    c.wrongPct = wrong;
    return c;
}

/// shadowmap and volume self-shadow, planar and blob do not, proxy bleeds softly, none draws nothing.
std::vector<AutoCandidate> table() {
    return {candidate("none", 0, 1.0, 40.0),
            candidate("shadowmap", kSelf | Effect::NonPlanarReceivers, 5.0, 0.4),
            candidate("volume", kSelf | Effect::NonPlanarReceivers, 9.0, 0.0),
            candidate("planar", kHard, 2.0, 0.1),
            candidate("blob", kSoft, 1.5, 12.0),
            candidate("proxy", kBleed | Effect::NonPlanarReceivers, 7.0, 3.0)};
}

std::string chosenName(EffectMask request, std::vector<AutoCandidate> candidates, double bound) {
    const AutoChoice choice = AutoSelection::choose(request, candidates, bound);
    if (!choice.chosen) return "nothing";
    const std::string& spec = candidates[*choice.chosen].spec;
    return spec.substr(0, spec.find(':'));
}

} // namespace

TEST(AutoSelection, PicksTheCheapestThatCoversTheRequestWithinTheBound) {
    struct Case {
        EffectMask request;
        double bound;
        const char* expected;
        const char* why;
    };
    const Case cases[] = {
        {0, 100.0, "none", "nothing asked for: the cheapest of all, the baseline included"},
        {0, 5.0, "none", "nothing asked for: the bound judges shadows, so none's 40% does not count"},
        {kHard, 5.0, "planar", "hard shadows alone: planar (2 ms) beats shadowmap (5 ms); none lacks them"},
        {kSelf, 5.0, "shadowmap", "self-shadowing rules planar out"},
        {kSelf, 0.1, "volume", "a 0.1% bound rules shadowmap (0.4%) out; volume is exact"},
        {kSelf, 0.0, "volume", "a zero bound keeps only the exact"},
        {kSoft, 20.0, "blob", "soft shadows within 20%: blob (1.5 ms)"},
        {kSoft, 5.0, "proxy", "within 5%: blob's 12% misses, proxy qualifies"},
        {kBleed, 5.0, "proxy", "colour bleeding: proxy alone declares it"},
        {kBleed, 1.0, "nothing", "proxy's 3% misses a 1% bound: no candidate"},
        {kSelf | Effect::SoftShadows, 100.0, "nothing", "no candidate declares both"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.why);
        EXPECT_EQ(chosenName(c.request, table(), c.bound), c.expected);
    }
}

TEST(AutoSelection, EveryVerdictSaysWhyAndTheChoiceIsNamed) {
    std::vector<AutoCandidate> candidates = table();
    const AutoChoice choice = AutoSelection::choose(kSelf, candidates, 0.1);
    ASSERT_TRUE(choice.chosen.has_value());
    EXPECT_EQ(candidates[0].verdict, "lacks hard_shadows+self_shadowing");
    EXPECT_EQ(candidates[1].verdict, "0.4% wrong > bound 0.1%");
    EXPECT_EQ(candidates[2].verdict, "chosen");
    EXPECT_EQ(candidates[3].verdict, "lacks self_shadowing");
    EXPECT_EQ(choice.reason, "volume: the cheapest of 1 candidate(s) delivering hard_shadows+self_shadowing "
                             "within 0.1% wrong (9 ms per frame, 0% wrong)");
}

TEST(AutoSelection, ARefusedCandidateIsNeverChosenHoweverCheapItLooks) {
    std::vector<AutoCandidate> candidates = table();
    candidates[1].measured = false; // shadowmap refused (say, a point light)
    candidates[1].refusal = "shadowmap: light 0 is a point light";
    candidates[1].costMs = 0.0;
    EXPECT_EQ(chosenName(kSelf, candidates, 5.0), "volume");
    AutoSelection::choose(kSelf, candidates, 5.0);
    EXPECT_EQ(candidates[1].verdict, "refused: shadowmap: light 0 is a point light");
}

TEST(AutoSelection, TheChoiceFollowsTheMeasuredCosts) {
    // The same candidates, only their measured costs swapped: the choice must swap with them.
    std::vector<AutoCandidate> candidates = table();
    EXPECT_EQ(chosenName(kSelf, candidates, 5.0), "shadowmap");
    candidates[1].costMs = 9.0;
    candidates[2].costMs = 5.0;
    EXPECT_EQ(chosenName(kSelf, candidates, 5.0), "volume");
    // Equal costs: the first listed (the registry's order), not a name.
    candidates[1].costMs = 5.0;
    EXPECT_EQ(chosenName(kSelf, candidates, 5.0), "shadowmap");
}

TEST(AutoSelection, TimeDecidesOnlyWhereEveryRoundAgreesAndExactWorkBreaksTheRest) {
    // Two qualifying candidates timed in the same interleaved calibration (batch "b1"), five rounds.
    auto timed = [](const std::string& name, std::vector<double> rounds, double work,
                    const std::string& batch) {
        AutoCandidate c = candidate(name, kHard, 0.0, 0.0);
        std::vector<double> sorted = rounds;
        std::sort(sorted.begin(), sorted.end());
        c.costMs = sorted[sorted.size() / 2];
        c.rounds = std::move(rounds);
        c.work = work;
        c.batch = batch;
        return c;
    };
    // planar: median 2.1 ms but slower than volume in round 2; volume: median 2.4 ms, a fifth the work.
    std::vector<AutoCandidate> tie = {timed("planar", {2.0, 2.1, 3.0, 2.0, 2.2}, 5e6, "b1"),
                                      timed("volume", {2.5, 2.0, 2.6, 2.4, 2.3}, 1e6, "b1")};
    AutoChoice choice = AutoSelection::choose(kHard, tie, 10.0);
    ASSERT_TRUE(choice.chosen.has_value());
    EXPECT_EQ(*choice.chosen, 1u)
        << "time cannot separate them, both are exact: the least exact work decides";
    EXPECT_NE(choice.reason.find("time could not separate planar and volume"), std::string::npos)
        << choice.reason;
    EXPECT_NE(choice.reason.find("volume does the least exact work"), std::string::npos) << choice.reason;
    EXPECT_EQ(tie[0].verdict, "qualifies; as fast as volume within the rounds, ranked after it (0% wrong, "
                              "5e+06 shader invocations)");
    // Time cannot separate them and planar is the more accurate: accuracy decides before the work.
    std::vector<AutoCandidate> accurate = {timed("planar", {2.0, 2.1, 3.0, 2.0, 2.2}, 5e6, "b1"),
                                           timed("volume", {2.5, 2.0, 2.6, 2.4, 2.3}, 1e6, "b1")};
    accurate[1].wrongPct = 2.0;
    choice = AutoSelection::choose(kHard, accurate, 10.0);
    EXPECT_EQ(*choice.chosen, 0u);
    EXPECT_NE(choice.reason.find("planar is the most accurate of them"), std::string::npos) << choice.reason;
    // A scene that asks for no shadow: the error measures shadows nobody asked for, the work decides.
    EXPECT_EQ(*AutoSelection::choose(0, accurate, 10.0).chosen, 1u);
    // planar faster in every round: time decides, whatever the work.
    std::vector<AutoCandidate> separated = {timed("planar", {2.0, 2.1, 3.0, 2.0, 2.2}, 5e6, "b1"),
                                            timed("volume", {2.5, 2.2, 3.1, 2.4, 2.3}, 1e6, "b1")};
    EXPECT_EQ(*AutoSelection::choose(kHard, separated, 10.0).chosen, 0u);
    // Timed in different calibrations: the rounds are not paired, the medians decide.
    std::vector<AutoCandidate> apart = {timed("planar", {2.0, 2.1, 3.0, 2.0, 2.2}, 5e6, "b1"),
                                        timed("volume", {2.5, 2.0, 2.6, 2.4, 2.3}, 1e6, "b2")};
    EXPECT_EQ(*AutoSelection::choose(kHard, apart, 10.0).chosen, 0u);
    // No exact work to compare (a context without pipeline statistics): the fastest median stays.
    std::vector<AutoCandidate> unknown = {timed("planar", {2.0, 2.1, 3.0, 2.0, 2.2}, -1.0, "b1"),
                                          timed("volume", {2.5, 2.0, 2.6, 2.4, 2.3}, 1e6, "b1")};
    EXPECT_EQ(*AutoSelection::choose(kHard, unknown, 10.0).chosen, 0u);
    // A candidate that misses the bound takes no part in the tie, however little work it does.
    std::vector<AutoCandidate> bounded = {timed("planar", {2.0, 2.1, 3.0, 2.0, 2.2}, 5e6, "b1"),
                                          timed("volume", {2.5, 2.0, 2.6, 2.4, 2.3}, 1e6, "b1")};
    bounded[1].wrongPct = 50.0;
    EXPECT_EQ(*AutoSelection::choose(kHard, bounded, 10.0).chosen, 0u);
}
