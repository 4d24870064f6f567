// The renderdiff convention of bench/golden/ImageDiff.h on hand-made images: counts by hand.
#include <gtest/gtest.h>

#include "bench/golden/ImageDiff.h"

using namespace sb;

namespace {

Image8 grey(int w, int h, uint8_t v) {
    return {w, h, 1, std::vector<uint8_t>(size_t(w) * size_t(h), v)};
}

TEST(ImageDiff, CountsPixelsOverTheChannelThreshold) {
    Image8 a = grey(10, 10, 100), b = a;
    b.pixels[3] = 102;  // within 2: passes the channel test
    b.pixels[50] = 103; // 3 > 2: fails
    b.pixels[99] = 0;   // 100: fails
    const DiffTolerance tol{2, 0.02};
    const ImageDiffResult r = ImageDiff::compare(a, b, tol);
    ASSERT_TRUE(r.comparable);
    EXPECT_EQ(r.failingPixels, 2u);
    EXPECT_EQ(r.maxChannelDiff, 100);
    EXPECT_DOUBLE_EQ(r.failingFraction(), 0.02);
    EXPECT_TRUE(r.passes(tol));         // 2% allowed, 2% failing
    EXPECT_FALSE(r.passes({2, 0.019})); // one pixel less allowed
}

TEST(ImageDiff, APixelFailsOnItsWorstChannel) {
    Image8 a{2, 1, 3, {10, 10, 10, 10, 10, 10}}, b = a;
    b.pixels[5] = 20; // second pixel's blue channel
    const ImageDiffResult r = ImageDiff::compare(a, b, {2, 0.0});
    EXPECT_EQ(r.failingPixels, 1u);
    EXPECT_EQ(r.pixels, 2u);
}

TEST(ImageDiff, DifferentSizesAreNotComparable) {
    const ImageDiffResult r = ImageDiff::compare(grey(4, 4, 0), grey(4, 5, 0), {2, 1.0});
    EXPECT_FALSE(r.comparable);
    EXPECT_FALSE(r.passes({255, 1.0}));
    EXPECT_NE(r.describe({2, 1.0}).find("4x4x1 expected, 4x5x1 rendered"), std::string::npos);
}

} // namespace
