#include "bench/golden/ImageDiff.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>

namespace sb {

namespace {

std::string sizeOf(const Image8& image) {
    return std::to_string(image.width) + "x" + std::to_string(image.height) + "x" +
           std::to_string(image.channels);
}

} // namespace

bool ImageDiffResult::passes(const DiffTolerance& tolerance) const {
    return comparable && failingFraction() <= tolerance.maxFailingFraction;
}

std::string ImageDiffResult::describe(const DiffTolerance& tolerance) const {
    if (!comparable) return mismatch;
    std::ostringstream out;
    out << "max diff " << maxChannelDiff << "/255, " << failingPixels << " of " << pixels << " pixels ("
        << failingFraction() * 100.0 << "%) over " << tolerance.maxChannelDiff << " (allowed "
        << tolerance.maxFailingFraction * 100.0 << "%)";
    return out.str();
}

ImageDiffResult ImageDiff::compare(const Image8& expected, const Image8& actual,
                                   const DiffTolerance& tolerance) {
    ImageDiffResult r;
    if (expected.width != actual.width || expected.height != actual.height ||
        expected.channels != actual.channels || expected.pixels.size() != actual.pixels.size()) {
        r.mismatch = "size " + sizeOf(expected) + " expected, " + sizeOf(actual) + " rendered";
        return r;
    }
    r.comparable = true;
    r.pixels = expected.pixelCount();
    const size_t channels = size_t(expected.channels);
    for (size_t p = 0; p < r.pixels; ++p) {
        int worst = 0;
        for (size_t c = 0; c < channels; ++c)
            worst = std::max(worst, std::abs(int(expected.pixels[p * channels + c]) -
                                             int(actual.pixels[p * channels + c])));
        r.maxChannelDiff = std::max(r.maxChannelDiff, worst);
        r.failingPixels += worst > tolerance.maxChannelDiff;
    }
    return r;
}

} // namespace sb
