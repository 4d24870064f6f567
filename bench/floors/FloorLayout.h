#pragma once
// Where a floor pass (bench/floors/FloorPass.h) puts its fragments: `N` fragments on a W x H target as
// screen-aligned rectangles of whole pixels (the floor draws each as a scissor box), every fragment one
// pixel of one rectangle. Whole-target layers first (a pass may shade more fragments than the target
// has pixels: a depth pass draws front and back faces), then the rest as 4-row bands, 4-high columns
// and one last column shorter than 4, so at most one 4x4 block of the remainder is partly covered
// (llvmpipe shades and counts fragments in 4x4 blocks).
#include <cstdint>
#include <vector>

namespace sb {

/// A rectangle of pixels [x0, x1) x [y0, y1), drawn `repeat` times.
struct FloorRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    uint64_t repeat = 1;
    /// The fragments it draws: its pixels times `repeat`.
    uint64_t fragments() const { return uint64_t(x1 - x0) * uint64_t(y1 - y0) * repeat; }
};

class FloorLayout {
public:
    /// The rectangles that draw exactly `fragments` fragments on a `width` x `height` target (their
    /// fragments() sum to it; none is empty). Throws sb::Error (BadInput) for a non-positive size.
    static std::vector<FloorRect> of(uint64_t fragments, int width, int height);
};

} // namespace sb
