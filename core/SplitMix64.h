#pragma once
// SplitMix64 (Steele, Lea, Flood 2014): the scene layout's random numbers. Hand-written on purpose:
// std::uniform_*_distribution is implementation-defined, and a seeded layout must place the same
// instances with every standard library, so CSV rows from different machines describe one scene.
#include <cstdint>

namespace sb {

class SplitMix64 {
public:
    explicit SplitMix64(uint64_t seed) : mState(seed) {}

    uint64_t next() {
        uint64_t z = (mState += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    /// Uniform in [0, 1): the top 53 bits scaled exactly into a double.
    double uniform() { return double(next() >> 11) * 0x1.0p-53; }
    /// Uniform in [lo, hi).
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

private:
    uint64_t mState;
};

} // namespace sb
