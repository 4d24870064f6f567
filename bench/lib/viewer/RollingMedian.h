#pragma once
// The median of the last N values added: the viewer's frame time. A median, not a mean or an
// exponential average, so that one slow frame (a shader compile, a descheduled llvmpipe thread) does
// not move the number shown.
#include <cstddef>
#include <vector>

namespace sb {

class RollingMedian {
public:
    /// Keeps the last `capacity` values (at least 1).
    explicit RollingMedian(size_t capacity);

    void add(double value);
    /// Median of the values kept: the middle one for an odd count, the mean of the two middle ones for
    /// an even count; 0 when there are none.
    double median() const;
    /// How many values the median is over now (at most the capacity).
    size_t count() const { return mValues.size(); }
    size_t capacity() const { return mCapacity; }
    void clear();

private:
    size_t mCapacity;
    size_t mNext = 0; ///< the slot the next value overwrites once full
    std::vector<double> mValues;
};

} // namespace sb
