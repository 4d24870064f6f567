#pragma once
// The order of base and head inside each measured round of the wall-time gate (layer C). Each round
// measures both builds back to back; what the gate compares is the per-round ratio head / base, so a
// slow drift of the machine (thermal state, a neighbour's job ramping up, caches warming) that is
// shared by both builds of a round cancels in the ratio, except for the part that grows between the
// first and the second measurement of that round. The schedule decides who pays that part.
//
//   Abba    rounds alternate A B, B A, A B, ... (A = base, B = head). Over each pair of rounds base
//           runs in slots 0 and 3 and head in slots 1 and 2: both have mean slot 1.5, so a drift that
//           is linear in time adds the same to both and the within-round bias flips sign each round
//           (+d, -d, +d, ...) instead of always favouring the build that runs first. Use it by
//           default: with 9 rounds the imbalance is one round's worth, not nine.
//   Random  each round's order is a fair coin from a seeded SplitMix64. ABBA's period of two rounds
//           can alias with something periodic on the machine (a job every other round); a random
//           order cannot, at the price of no guaranteed balance. The seed is recorded with the run so
//           the schedule can be replayed.
#include <cstdint>
#include <vector>

namespace sb::ci {

/// Which build runs first in one round.
enum class Order { BaseFirst, HeadFirst };

/// How the orders of successive rounds are chosen (see above).
enum class Scheme { Abba, Random };

/// One Order per round: Abba gives BaseFirst, HeadFirst, BaseFirst, ... (the seed is unused); Random
/// draws each round from SplitMix64(seed), so one seed gives one schedule on every machine.
/// rounds < 1 is bad input (sb::Error).
std::vector<Order> interleave(int rounds, uint64_t seed, Scheme scheme);

} // namespace sb::ci
