#include "bench/golden/GoldenDiff.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "bench/lib/images/AccuracyImages.h"
#include "bench/lib/images/DifferenceMap.h"
#include "bench/lib/images/ErrorMap.h"
#include "bench/lib/output/ImageWriter.h"

namespace sb {

namespace {

/// Channel `c` of an 8-bit image as visibility in [0, 1].
std::vector<float> channel(const Image8& image, int c) {
    std::vector<float> out(image.pixelCount());
    for (size_t p = 0; p < out.size(); ++p)
        out[p] = float(image.pixels[p * size_t(image.channels) + size_t(c)]) / 255.0f;
    return out;
}

/// Luminance in [0, 1] (Rec. 709 weights over the first three channels; grey for fewer).
std::vector<float> luminance(const Image8& image) {
    if (image.channels < 3) return channel(image, 0);
    std::vector<float> out(image.pixelCount());
    for (size_t p = 0; p < out.size(); ++p) {
        const uint8_t* px = &image.pixels[p * size_t(image.channels)];
        out[p] = (0.2126f * float(px[0]) + 0.7152f * float(px[1]) + 0.0722f * float(px[2])) / 255.0f;
    }
    return out;
}

float maxAbsDifference(const std::vector<float>& a, const std::vector<float>& b) {
    float m = 0.0f;
    for (size_t i = 0; i < a.size(); ++i) m = std::max(m, std::fabs(a[i] - b[i]));
    return m;
}

void writeRgb(const std::string& path, const RgbImage& image) {
    ImageWriter::writeAtomic(path, image.width(), image.height(), 3, image.bytes().data());
}

} // namespace

std::string GoldenDiff::fileStem(const std::string& cell) {
    std::string out = cell;
    std::replace(out.begin(), out.end(), '/', '.');
    return AccuracyImages::fileLabel(out);
}

std::vector<std::string> GoldenDiff::write(const std::string& dir, const std::string& cell,
                                           const GoldenChange& change) {
    const Image8& golden = change.golden;
    const Image8& rendered = change.rendered;
    const std::vector<uint8_t> everywhere(golden.pixelCount(), 1);
    const std::string stem = (std::filesystem::path(dir) / fileStem(cell)).string();
    std::vector<std::string> written;
    if (change.kind == "visibility") {
        for (int c = 0; c < golden.channels; ++c) {
            const std::vector<float> ref = channel(golden, c), tech = channel(rendered, c);
            const float largest = maxAbsDifference(tech, ref);
            if (largest == 0.0f) continue; // this light did not change
            const std::string base = stem + ".visibility.light" + std::to_string(c);
            writeRgb(base + ".error.png",
                     ErrorMap::build(tech, ref, everywhere, golden.width, golden.height).image());
            writeRgb(base + ".signed.png",
                     DifferenceMap::build(tech, ref, everywhere, golden.width, golden.height,
                                          DifferenceMap::niceScale(largest)));
            written.push_back(base + ".error.png");
            written.push_back(base + ".signed.png");
        }
    } else {
        const std::vector<float> ref = luminance(golden), tech = luminance(rendered);
        const std::string path = stem + "." + change.kind + ".signed.png";
        writeRgb(path, DifferenceMap::build(tech, ref, everywhere, golden.width, golden.height,
                                            DifferenceMap::niceScale(maxAbsDifference(tech, ref))));
        written.push_back(path);
    }
    return written;
}

} // namespace sb
