#include "bench/lib/bisect/BisectSearch.h"

#include <optional>

#include "core/Error.h"

namespace sb {

namespace {

/// The untested index of [lo, hi) nearest to `mid` (mid first, then mid+1, mid-1, mid+2 ...), or none
/// when every index there was skipped. Moving to a neighbour keeps the halves near even, so a skip costs
/// about one evaluation.
std::optional<size_t> probe(size_t lo, size_t hi, const std::vector<bool>& skipped) {
    const size_t mid = lo + (hi - 1 - lo) / 2;
    for (size_t d = 0; d < hi - lo; ++d) {
        if (mid + d < hi && !skipped[mid + d]) return mid + d;
        if (d > 0 && mid >= lo + d && !skipped[mid - d]) return mid - d;
    }
    return std::nullopt;
}

} // namespace

BisectSearch::BisectSearch(size_t count) : mCount(count) {
    if (count == 0) throw Error("bisect: no commit between GOOD and BAD", ExitCode::BadInput);
}

size_t BisectSearch::maxEvaluations(size_t count) {
    size_t bits = 0;
    while ((size_t(1) << bits) < count + 1) ++bits;
    return bits;
}

BisectOutcome BisectSearch::run(const std::function<BisectVerdict(size_t)>& evaluate) const {
    // The first Bad index lies in [lo, hi]; hi == mCount stands for "none differs". Every index below
    // lo was Good (or is GOOD itself), hi was Bad (or is the sentinel).
    size_t lo = 0, hi = mCount;
    std::vector<bool> skipped(mCount, false);
    BisectOutcome out;
    while (lo < hi) {
        const std::optional<size_t> at = probe(lo, hi, skipped);
        if (!at) break;
        out.evaluated.push_back(*at);
        switch (evaluate(*at)) {
        case BisectVerdict::Good:
            lo = *at + 1;
            break;
        case BisectVerdict::Bad:
            hi = *at;
            break;
        case BisectVerdict::Skip:
            skipped[*at] = true;
            out.skipped.push_back(*at);
            break;
        }
    }
    if (lo == hi) {
        out.kind = hi == mCount ? BisectOutcome::Kind::NotFound : BisectOutcome::Kind::Found;
        out.firstBad = hi;
        return out;
    }
    out.kind = BisectOutcome::Kind::Undecided;
    for (size_t i = lo; i < hi; ++i) out.candidates.push_back(i); // all skipped
    if (hi < mCount)
        out.candidates.push_back(hi);
    else
        out.mayBeNone = true;
    return out;
}

} // namespace sb
