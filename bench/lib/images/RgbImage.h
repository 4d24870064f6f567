#pragma once
// An 8-bit RGB picture in memory, top row first: what the error maps, difference maps and contact sheets
// (this folder) draw into before bench/lib/output/ImageWriter writes them as PNG. Pure CPU, no GL, so every
// picture is unit-testable pixel by pixel (tests/ErrorMapTest.cpp).
#include <cstdint>
#include <vector>

namespace sb {

struct Rgb {
    uint8_t r = 0, g = 0, b = 0;
    friend bool operator==(const Rgb&, const Rgb&) = default;
};

class RgbImage {
public:
    RgbImage() = default;
    /// `width` x `height` pixels of `fill`; a negative size counts as 0.
    RgbImage(int width, int height, Rgb fill = {});

    int width() const { return mWidth; }
    int height() const { return mHeight; }
    bool empty() const { return mPixels.empty(); }
    /// The interleaved RGB bytes, row y at offset 3 * y * width.
    const std::vector<uint8_t>& bytes() const { return mPixels; }

    bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < mWidth && y < mHeight; }
    /// The pixel at (x, y); (x, y) must lie inside.
    Rgb at(int x, int y) const;
    /// Sets (x, y); a pixel outside the picture is ignored, so drawing clips at the border.
    void set(int x, int y, Rgb c);
    /// Fills the rectangle [x, x + w) x [y, y + h), clipped to the picture.
    void fillRect(int x, int y, int w, int h, Rgb c);
    /// Copies `source` with its top-left corner at (x, y), clipped to the picture.
    void blit(const RgbImage& source, int x, int y);
    /// The same picture upside down: GL read-backs are bottom row first, pictures top row first.
    RgbImage flippedVertically() const;

private:
    int mWidth = 0, mHeight = 0;
    std::vector<uint8_t> mPixels;
};

} // namespace sb
