#pragma once
// GL read-backs (and the buffers of bench/lib/measure/AccuracyEvaluator.h's Sample) are bottom row first;
// pictures are top row first.
#include <algorithm>
#include <vector>

namespace sb {

/// `values` (width * height, one per pixel) with the row order reversed.
template <class T>
std::vector<T> flipRows(const std::vector<T>& values, int width, int height) {
    std::vector<T> out(values.size());
    const size_t row = size_t(std::max(0, width));
    for (int y = 0; y < height && size_t(y + 1) * row <= values.size(); ++y)
        std::copy_n(values.begin() + std::ptrdiff_t(size_t(y) * row), row,
                    out.begin() + std::ptrdiff_t(size_t(height - 1 - y) * row));
    return out;
}

} // namespace sb
