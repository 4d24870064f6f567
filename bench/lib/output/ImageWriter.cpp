#include "bench/lib/output/ImageWriter.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "bench/lib/output/AtomicFile.h"
#include "core/Error.h"
#include "core/PngFile.h"

namespace sb {

void ImageWriter::checkWritable(const std::string& path, const std::string& option) {
    if (path.empty()) throw Error(option + ": the path is empty");
    AtomicFile::checkWritable(path, "image"); // a folder, device or missing parent first: the bigger mistake
    if (!PngFile::hasPngExtension(path))
        throw Error(option + " " + path + ": images are written as PNG (name the file .png)");
}

void ImageWriter::writeAtomic(const std::string& path, int width, int height, int channels,
                              const unsigned char* pixels) {
    PngFile::write(path, width, height, channels, pixels); // temp file, checks and rename live there
}

void ImageWriter::writeColor(const FrameTargets& targets, const std::string& path) {
    writeColor(targets.width(), targets.height(), targets.readColorRGBA8(), path);
}

void ImageWriter::writeColor(int w, int h, const std::vector<unsigned char>& rgba, const std::string& path) {
    std::vector<unsigned char> rgb(size_t(w) * size_t(h) * 3);
    for (int y = 0; y < h; ++y) // GL rows are bottom-up; images are top-down
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c)
                rgb[(size_t(y) * size_t(w) + size_t(x)) * 3 + size_t(c)] =
                    rgba[(size_t(h - 1 - y) * size_t(w) + size_t(x)) * 4 + size_t(c)];
    writeAtomic(path, w, h, 3, rgb.data());
}

void ImageWriter::writeVisibility(const FrameTargets& targets, int light, const std::string& path) {
    writeVisibility(targets.width(), targets.height(), targets.readVisibilityRGBA32F(), light, path);
}

void ImageWriter::writeVisibility(int w, int h, const std::vector<float>& vis, int light,
                                  const std::string& path) {
    std::vector<unsigned char> grey(size_t(w) * size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float v = vis[(size_t(h - 1 - y) * size_t(w) + size_t(x)) * 4 + size_t(light)];
            if (!std::isfinite(v)) v = 0.0f;
            grey[size_t(y) * size_t(w) + size_t(x)] =
                (unsigned char)std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f);
        }
    writeAtomic(path, w, h, 1, grey.data());
}

} // namespace sb
