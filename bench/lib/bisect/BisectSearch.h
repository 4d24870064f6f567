#pragma once
// The search of `bench bisect`, apart from building and running: a first-parent history GOOD..BAD as
// the indices 0..count-1 (0 the commit after GOOD, count-1 BAD), a predicate that says of one index
// whether its signal still equals GOOD's (Good), differs (Bad) or could not be measured (Skip: the
// commit did not build or run, as `git bisect skip`), and a binary search for the first Bad index.
//
// The answer is one of count + 1 outcomes (an index, or "no index differs"), so the search evaluates
// at most ceil(log2(count + 1)) <= ceil(log2 count) + 1 indices when nothing is skipped; each Skip
// costs one evaluation more and moves the probe to the nearest untested index. When only skipped
// indices are left between the last Good and the first Bad, the answer is undecided and the outcome
// lists the indices it may be (as git bisect's "only 'skip'ped commits left to test").
//
//     BisectSearch search(64);
//     BisectOutcome o = search.run([&](size_t i) { return i >= 40 ? BisectVerdict::Bad : BisectVerdict::Good;
//     });
//     // o.kind == Found, o.firstBad == 40, o.evaluations() <= 7
#include <cstddef>
#include <functional>
#include <vector>

namespace sb {

enum class BisectVerdict { Good, Bad, Skip };

struct BisectOutcome {
    enum class Kind {
        Found,     ///< firstBad is the first index whose signal differs from GOOD's
        NotFound,  ///< every index up to the last equals GOOD (the last was evaluated Good)
        Undecided, ///< skipped indices hide the answer: it is one of `candidates`
    };
    Kind kind = Kind::NotFound;
    size_t firstBad = 0;            ///< Found only
    std::vector<size_t> candidates; ///< Undecided: the skipped indices it may be, then the first Bad
                                    ///< index if one was seen
    bool mayBeNone = false;         ///< Undecided with no Bad index seen: perhaps nothing differs
    std::vector<size_t> skipped;    ///< every index evaluated Skip, in evaluation order
    std::vector<size_t> evaluated;  ///< every index evaluated, in order (skipped included)
    size_t evaluations() const { return evaluated.size(); }
};

class BisectSearch {
public:
    /// A history of `count` commits after GOOD (count >= 1).
    explicit BisectSearch(size_t count);
    /// Runs the search, calling `evaluate` once per probed index (never twice for one index).
    BisectOutcome run(const std::function<BisectVerdict(size_t)>& evaluate) const;
    /// ceil(log2(count + 1)): the most evaluations a search without skips makes (count + 1 outcomes).
    /// It is at most ceil(log2 count) + 1, and equals ceil(log2 count) unless count is a power of two.
    static size_t maxEvaluations(size_t count);

private:
    size_t mCount;
};

} // namespace sb
