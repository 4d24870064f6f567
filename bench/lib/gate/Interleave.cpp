#include "bench/lib/gate/Interleave.h"

#include <string>

#include "core/Error.h"
#include "core/SplitMix64.h"

namespace sb::ci {

std::vector<Order> interleave(int rounds, uint64_t seed, Scheme scheme) {
    if (rounds < 1)
        throw Error("interleave: rounds must be at least 1 (got " + std::to_string(rounds) + ")",
                    ExitCode::BadInput);
    std::vector<Order> out;
    out.reserve(size_t(rounds));
    // SplitMix64 rather than std::bernoulli_distribution: the standard distributions are
    // implementation-defined, and a recorded seed must replay the same schedule everywhere.
    SplitMix64 rng(seed);
    for (int i = 0; i < rounds; ++i) {
        if (scheme == Scheme::Abba)
            out.push_back(i % 2 == 0 ? Order::BaseFirst : Order::HeadFirst);
        else
            out.push_back((rng.next() >> 63) == 0 ? Order::BaseFirst : Order::HeadFirst);
    }
    return out;
}

} // namespace sb::ci
