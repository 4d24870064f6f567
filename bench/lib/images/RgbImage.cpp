#include "bench/lib/images/RgbImage.h"

#include <algorithm>
#include <cstring>

namespace sb {

RgbImage::RgbImage(int width, int height, Rgb fill)
    : mWidth(std::max(0, width)), mHeight(std::max(0, height)),
      mPixels(size_t(mWidth) * size_t(mHeight) * 3) {
    for (size_t i = 0; i < mPixels.size(); i += 3) {
        mPixels[i] = fill.r;
        mPixels[i + 1] = fill.g;
        mPixels[i + 2] = fill.b;
    }
}

Rgb RgbImage::at(int x, int y) const {
    const size_t i = (size_t(y) * size_t(mWidth) + size_t(x)) * 3;
    return {mPixels[i], mPixels[i + 1], mPixels[i + 2]};
}

void RgbImage::set(int x, int y, Rgb c) {
    if (!contains(x, y)) return;
    const size_t i = (size_t(y) * size_t(mWidth) + size_t(x)) * 3;
    mPixels[i] = c.r;
    mPixels[i + 1] = c.g;
    mPixels[i + 2] = c.b;
}

void RgbImage::fillRect(int x, int y, int w, int h, Rgb c) {
    const int x0 = std::max(0, x), y0 = std::max(0, y);
    const int x1 = std::min(mWidth, x + w), y1 = std::min(mHeight, y + h);
    for (int yy = y0; yy < y1; ++yy)
        for (int xx = x0; xx < x1; ++xx) set(xx, yy, c);
}

void RgbImage::blit(const RgbImage& source, int x, int y) {
    for (int sy = 0; sy < source.height(); ++sy) {
        const int ty = y + sy;
        if (ty < 0 || ty >= mHeight) continue;
        const int sx0 = std::max(0, -x), sx1 = std::min(source.width(), mWidth - x);
        if (sx1 <= sx0) continue;
        std::memcpy(&mPixels[(size_t(ty) * size_t(mWidth) + size_t(x + sx0)) * 3],
                    &source.mPixels[(size_t(sy) * size_t(source.width()) + size_t(sx0)) * 3],
                    size_t(sx1 - sx0) * 3);
    }
}

RgbImage RgbImage::flippedVertically() const {
    RgbImage out(mWidth, mHeight);
    const size_t row = size_t(mWidth) * 3;
    for (int y = 0; y < mHeight; ++y)
        std::memcpy(&out.mPixels[size_t(mHeight - 1 - y) * row], &mPixels[size_t(y) * row], row);
    return out;
}

} // namespace sb
