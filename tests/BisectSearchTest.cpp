// The search of `bench bisect` apart from building (bench/lib/bisect/BisectSearch.h): a predicate over
// the indices of a history, hand-checked cases, and the bound on evaluations. Every expected index and
// probe order below was worked out by hand from the rule "probe lo + (hi - 1 - lo) / 2 of the open
// range [lo, hi), else its nearest untested neighbour, mid + 1 before mid - 1"; the bound is
// ceil(log2 N) + 1, computed here without the class's own helper.
#include <cmath>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "bench/lib/bisect/BisectSearch.h"

using namespace sb;

namespace {

/// A history of `n` commits whose signal changes at `firstBad` (n: never), with `skipped` unbuildable.
struct History {
    size_t n;
    size_t firstBad;
    std::set<size_t> skipped;
};

struct Probed {
    BisectOutcome outcome;
    std::vector<size_t> calls; ///< every index the predicate was asked about
};

Probed search(const History& h) {
    Probed r;
    r.outcome = BisectSearch(h.n).run([&](size_t i) {
        r.calls.push_back(i);
        if (h.skipped.count(i)) return BisectVerdict::Skip;
        return i >= h.firstBad ? BisectVerdict::Bad : BisectVerdict::Good;
    });
    return r;
}

/// ceil(log2 n) + 1, by counting: the bound the brief and results/bisect/README.md state.
size_t bound(size_t n) {
    size_t bits = 0;
    while ((size_t(1) << bits) < n) ++bits;
    return bits + 1;
}

} // namespace

TEST(BisectSearch, FirstBadInTheMiddleTakesTheHandCheckedProbes) {
    // n = 8, first bad 5: [0,8) probes 3 (good, lo 4), [4,8) probes 5 (bad, hi 5), [4,5) probes 4 (good).
    const Probed r = search({8, 5, {}});
    EXPECT_EQ(r.outcome.kind, BisectOutcome::Kind::Found);
    EXPECT_EQ(r.outcome.firstBad, 5u);
    EXPECT_EQ(r.calls, (std::vector<size_t>{3, 5, 4}));
    EXPECT_EQ(r.outcome.evaluated, r.calls);
}

TEST(BisectSearch, FirstBadAtTheFirstCommit) {
    // n = 8, first bad 0: probes 3, 1, 0, all bad.
    const Probed r = search({8, 0, {}});
    EXPECT_EQ(r.outcome.kind, BisectOutcome::Kind::Found);
    EXPECT_EQ(r.outcome.firstBad, 0u);
    EXPECT_EQ(r.calls, (std::vector<size_t>{3, 1, 0}));
}

TEST(BisectSearch, FirstBadAtTheLastCommit) {
    // n = 8, first bad 7 (BAD itself): probes 3, 5, 6 good, then 7 bad: 4 = ceil(log2 8) + 1.
    const Probed r = search({8, 7, {}});
    EXPECT_EQ(r.outcome.kind, BisectOutcome::Kind::Found);
    EXPECT_EQ(r.outcome.firstBad, 7u);
    EXPECT_EQ(r.calls, (std::vector<size_t>{3, 5, 6, 7}));
    EXPECT_LE(r.calls.size(), bound(8));
}

TEST(BisectSearch, OneCommitIsProbedOnce) {
    EXPECT_EQ(search({1, 0, {}}).outcome.kind, BisectOutcome::Kind::Found);
    EXPECT_EQ(search({1, 0, {}}).calls.size(), 1u);
    EXPECT_EQ(search({1, 1, {}}).outcome.kind, BisectOutcome::Kind::NotFound);
}

TEST(BisectSearch, SameSignalAtGoodAndBadIsNotFound) {
    // Nothing changes in 64 commits: every probe good, the last one BAD itself.
    const Probed r = search({64, 64, {}});
    EXPECT_EQ(r.outcome.kind, BisectOutcome::Kind::NotFound);
    EXPECT_EQ(r.calls.back(), 63u) << "not found must have measured BAD";
    EXPECT_LE(r.calls.size(), bound(64));
}

TEST(BisectSearch, SkippedCommitAfterTheAnswerIsSearchedAround) {
    // n = 8, first bad 5, 6 does not build: 3 good, 5 bad, 4 good; 6 is never asked.
    const Probed r = search({8, 5, {6}});
    EXPECT_EQ(r.outcome.kind, BisectOutcome::Kind::Found);
    EXPECT_EQ(r.outcome.firstBad, 5u);
    EXPECT_TRUE(r.outcome.skipped.empty());
}

TEST(BisectSearch, SkippedFirstBadLeavesItAndTheNextAsCandidates) {
    // n = 8, first bad 5 does not build: 3 good, 5 skip, 6 (mid + 1) bad, [4,6) probes 4 good, [5,6)
    // holds only 5, skipped: the answer is 5 or 6, as git bisect says.
    const Probed r = search({8, 5, {5}});
    EXPECT_EQ(r.outcome.kind, BisectOutcome::Kind::Undecided);
    EXPECT_EQ(r.calls, (std::vector<size_t>{3, 5, 6, 4}));
    EXPECT_EQ(r.outcome.candidates, (std::vector<size_t>{5, 6}));
    EXPECT_FALSE(r.outcome.mayBeNone);
    EXPECT_EQ(r.outcome.skipped, (std::vector<size_t>{5}));
}

TEST(BisectSearch, SkippedCommitBeforeTheAnswerLeavesBoth) {
    // n = 8, first bad 5, 4 does not build: 3 good, 5 bad, [4,5) holds only 4: candidates 4 and 5.
    const Probed r = search({8, 5, {4}});
    EXPECT_EQ(r.outcome.kind, BisectOutcome::Kind::Undecided);
    EXPECT_EQ(r.outcome.candidates, (std::vector<size_t>{4, 5}));
}

TEST(BisectSearch, AllSkippedSaysSoAndThatNothingMayHaveChanged) {
    // n = 4: probes 1, 2 (mid + 1), 0 (mid - 1), 3, each once.
    const Probed r = search({4, 2, {0, 1, 2, 3}});
    EXPECT_EQ(r.outcome.kind, BisectOutcome::Kind::Undecided);
    EXPECT_EQ(r.calls, (std::vector<size_t>{1, 2, 0, 3}));
    EXPECT_EQ(r.outcome.candidates, (std::vector<size_t>{0, 1, 2, 3}));
    EXPECT_TRUE(r.outcome.mayBeNone);
}

TEST(BisectSearch, EveryAnswerOfEveryLengthWithinTheBound) {
    // Exhaustive over n = 1..130 and every first bad 0..n (n: none): the right answer, no index asked
    // twice, and at most ceil(log2 n) + 1 evaluations (ceil(log2(n + 1)) exactly, its own helper).
    for (size_t n = 1; n <= 130; ++n)
        for (size_t first = 0; first <= n; ++first) {
            const Probed r = search({n, first, {}});
            ASSERT_EQ(r.outcome.kind, first == n ? BisectOutcome::Kind::NotFound : BisectOutcome::Kind::Found)
                << n << " " << first;
            if (first < n) {
                ASSERT_EQ(r.outcome.firstBad, first) << n;
            }
            ASSERT_LE(r.calls.size(), bound(n)) << "n " << n << ", first bad " << first;
            ASSERT_LE(r.calls.size(), BisectSearch::maxEvaluations(n));
            ASSERT_EQ(std::set<size_t>(r.calls.begin(), r.calls.end()).size(), r.calls.size());
        }
}

TEST(BisectSearch, EmptyHistoryIsBadInput) {
    EXPECT_THROW(BisectSearch(0), std::exception);
}
