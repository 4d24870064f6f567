#pragma once
// Image comparison under the renderdiff convention: a pixel fails when any channel differs by more than
// a per-channel threshold, and an image fails when the fraction of failing pixels exceeds a second
// threshold. Two numbers, each with its reason at the call site, instead of one opaque "similarity".
#include <cstdint>
#include <string>
#include <vector>

namespace sb {

/// An 8-bit image, top row first, `channels` interleaved values per pixel.
struct Image8 {
    int width = 0, height = 0, channels = 0;
    std::vector<uint8_t> pixels;
    size_t pixelCount() const { return size_t(width) * size_t(height); }
    bool empty() const { return pixels.empty(); }
};

struct DiffTolerance {
    int maxChannelDiff = 0;          ///< a pixel fails when some channel differs by more than this
    double maxFailingFraction = 0.0; ///< the image fails when more than this fraction of pixels fail
};

struct ImageDiffResult {
    bool comparable = false; ///< same size and channel count
    int maxChannelDiff = 0;  ///< over every pixel
    uint64_t failingPixels = 0, pixels = 0;
    double failingFraction() const { return pixels ? double(failingPixels) / double(pixels) : 0.0; }
    bool passes(const DiffTolerance& tolerance) const;
    /// "max diff 3/255, 12 of 4096 pixels (0.29%) over 2" or "size 64x64x1 vs 32x32x1".
    std::string describe(const DiffTolerance& tolerance) const;
    std::string mismatch; ///< why the images are not comparable
};

class ImageDiff {
public:
    static ImageDiffResult compare(const Image8& expected, const Image8& actual,
                                   const DiffTolerance& tolerance);
};

} // namespace sb
