#include "bench/lib/viewer/RollingMedian.h"

#include <algorithm>

namespace sb {

RollingMedian::RollingMedian(size_t capacity) : mCapacity(std::max<size_t>(capacity, 1)) {
    mValues.reserve(mCapacity);
}

void RollingMedian::add(double value) {
    if (mValues.size() < mCapacity) {
        mValues.push_back(value);
        return;
    }
    mValues[mNext] = value;
    mNext = (mNext + 1) % mCapacity;
}

double RollingMedian::median() const {
    if (mValues.empty()) return 0.0;
    std::vector<double> v = mValues;
    const size_t mid = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(mid), v.end());
    const double upper = v[mid];
    if (v.size() % 2 == 1) return upper;
    // The lower middle value is the largest of the elements before mid.
    const double lower = *std::max_element(v.begin(), v.begin() + std::ptrdiff_t(mid));
    return 0.5 * (lower + upper);
}

void RollingMedian::clear() {
    mValues.clear();
    mNext = 0;
}

} // namespace sb
