#include "bench/golden/GoldenImage.h"

#include <filesystem>

#include "bench/lib/output/ImageWriter.h"
#include "core/Error.h"
#include "core/PngFile.h"

namespace sb {

Image8 GoldenImage::read(const std::string& path) {
    PngImage png;
    try {
        png = PngFile::read8(path);
    } catch (const Error& e) {
        throw Error(std::string("golden: ") + e.what(), e.code());
    }
    Image8 image;
    image.width = png.width;
    image.height = png.height;
    image.channels = png.channels;
    image.pixels = std::move(png.pixels);
    return image;
}

void GoldenImage::write(const std::string& path, const Image8& image) {
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
    ImageWriter::writeAtomic(path, image.width, image.height, image.channels, image.pixels.data());
}

} // namespace sb
