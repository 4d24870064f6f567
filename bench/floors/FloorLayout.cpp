#include "bench/floors/FloorLayout.h"

#include <algorithm>
#include <string>

#include "core/Error.h"

namespace sb {

namespace {
/// llvmpipe's shading block side: the remainder is laid out in bands of this height.
constexpr int kBlock = 4;

void add(std::vector<FloorRect>& out, int x0, int y0, int x1, int y1, uint64_t repeat = 1) {
    if (x1 > x0 && y1 > y0 && repeat > 0) out.push_back({x0, y0, x1, y1, repeat});
}
} // namespace

std::vector<FloorRect> FloorLayout::of(uint64_t fragments, int width, int height) {
    if (width <= 0 || height <= 0)
        throw Error("floor layout: target size " + std::to_string(width) + "x" + std::to_string(height) +
                    " is not positive");
    std::vector<FloorRect> out;
    const uint64_t W = uint64_t(width), pixels = W * uint64_t(height);
    add(out, 0, 0, width, height, fragments / pixels);
    uint64_t rest = fragments % pixels;
    // Bands of kBlock full rows where the target has that many rows; a target under kBlock rows high
    // takes full rows instead.
    const int band = std::min(kBlock, height);
    const uint64_t bands = rest / (W * uint64_t(band));
    const int y = int(bands) * band;
    add(out, 0, 0, width, y);
    rest -= bands * W * uint64_t(band);
    // What is left is less than one band: columns `band` high, then one shorter column.
    const int h = std::min(band, height - y);
    const uint64_t columns = rest / uint64_t(h);
    add(out, 0, y, int(columns), y + h);
    add(out, int(columns), y, int(columns) + 1, y + int(rest % uint64_t(h)));
    return out;
}

} // namespace sb
