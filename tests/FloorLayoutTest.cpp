// FloorLayout (bench/floors/FloorLayout.h): the rectangles of a floor pass cover exactly the fragments
// asked for, inside the target, each pixel of the remainder once, with at most one 4x4 block partly
// covered. The answer is counted independently here, pixel by pixel on a grid.
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <vector>

#include "bench/floors/FloorLayout.h"
#include "core/Error.h"

namespace sb {
namespace {

struct Case {
    const char* name;
    uint64_t fragments;
    int width, height;
};

const Case kCases[] = {
    {"none", 0, 64, 64},
    {"one", 1, 64, 64},
    {"one short of a band", 4 * 64 - 1, 64, 64},
    {"ragged remainder", 1234, 64, 64},
    {"exactly the target", 64 * 64, 64, 64},
    {"one layer and five", 64 * 64 + 5, 64, 64},
    {"three layers and a remainder", 3 * 64 * 64 + 777, 64, 64},
    {"odd size", 5000, 37, 23},
    {"two rows high", 57, 40, 2},
    {"one column wide", 9, 1, 16},
    {"a depth pass of the horse on a 2048 map", 2884128, 2048, 2048},
};

TEST(FloorLayout, CoversExactlyTheFragmentsInsideTheTarget) {
    for (const Case& c : kCases) {
        SCOPED_TRACE(c.name);
        const std::vector<FloorRect> rects = FloorLayout::of(c.fragments, c.width, c.height);
        uint64_t sum = 0;
        // The remainder (rectangles drawn once) marked pixel by pixel: each pixel at most once.
        std::vector<int> once(size_t(c.width) * size_t(c.height), 0);
        uint64_t layers = 0;
        for (const FloorRect& r : rects) {
            EXPECT_GT(r.fragments(), 0u) << "an empty rectangle";
            EXPECT_GE(r.x0, 0);
            EXPECT_GE(r.y0, 0);
            EXPECT_LE(r.x1, c.width);
            EXPECT_LE(r.y1, c.height);
            sum += r.fragments();
            const bool whole = r.x0 == 0 && r.y0 == 0 && r.x1 == c.width && r.y1 == c.height;
            if (whole) { // the layers: the remainder is less than the target, so never whole
                layers += r.repeat;
                continue;
            }
            EXPECT_EQ(r.repeat, 1u);
            for (int y = r.y0; y < r.y1; ++y)
                for (int x = r.x0; x < r.x1; ++x) ++once[size_t(y) * size_t(c.width) + size_t(x)];
        }
        EXPECT_EQ(sum, c.fragments);
        uint64_t marked = 0;
        for (int v : once) {
            EXPECT_LE(v, 1) << "a pixel of the remainder drawn twice";
            marked += uint64_t(v);
        }
        EXPECT_EQ(layers * uint64_t(c.width) * uint64_t(c.height) + marked, c.fragments);
        // llvmpipe shades 4x4 blocks: at most one block of the remainder is partly covered (targets whose
        // sides are multiples of 4).
        if (c.width % 4 == 0 && c.height % 4 == 0) {
            int partial = 0;
            for (int by = 0; by < c.height; by += 4)
                for (int bx = 0; bx < c.width; bx += 4) {
                    int n = 0;
                    for (int y = by; y < by + 4; ++y)
                        for (int x = bx; x < bx + 4; ++x) n += once[size_t(y) * size_t(c.width) + size_t(x)];
                    partial += n > 0 && n < 16;
                }
            EXPECT_LE(partial, 1);
        }
    }
}

TEST(FloorLayout, RefusesATargetWithoutPixels) {
    EXPECT_THROW(FloorLayout::of(10, 0, 64), Error);
    EXPECT_THROW(FloorLayout::of(10, 64, -1), Error);
}

} // namespace
} // namespace sb
