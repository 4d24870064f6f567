#pragma once
// A hand-made matrix cell's images for the matrix-check tests (MatrixCheckTest, MatrixVariantsTest): a
// square one-light frame whose left `shadowed` columns are in shadow (visibility 0, colour 20) and the rest
// lit (visibility 1, colour 200), in the 8-bit images and the float read-back alike. The cell's accuracy is
// the caller's: each test states what its reference judged.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "bench/golden/GoldenMatrix.h"

namespace sb::test {

inline void paintColumns(MatrixCell& cell, int size, int shadowed) {
    cell.visibility = {size, size, 1, std::vector<uint8_t>(size_t(size * size))};
    cell.colour = {size, size, 3, std::vector<uint8_t>(size_t(size * size * 3))};
    cell.visibilityFloat.assign(size_t(size * size), 1.0f);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const size_t p = size_t(y * size + x);
            const bool dark = x < shadowed;
            cell.visibility.pixels[p] = dark ? 0 : 255;
            cell.visibilityFloat[p] = dark ? 0.0f : 1.0f;
            for (int c = 0; c < 3; ++c) cell.colour.pixels[p * 3 + size_t(c)] = dark ? 20 : 200;
        }
}

} // namespace sb::test
