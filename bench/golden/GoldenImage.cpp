#include "bench/golden/GoldenImage.h"

#include <filesystem>

#include <OpenImageIO/imageio.h>

#include "bench/output/ImageWriter.h"
#include "core/Error.h"

namespace sb {

Image8 GoldenImage::read(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw Error("cannot read golden '" + path + "': " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    Image8 image;
    image.width = spec.width;
    image.height = spec.height;
    image.channels = spec.nchannels;
    image.pixels.resize(image.pixelCount() * size_t(image.channels));
    if (!in->read_image(0, 0, 0, image.channels, OIIO::TypeDesc::UINT8, image.pixels.data()))
        throw Error("cannot read golden '" + path + "': " + in->geterror());
    in->close();
    return image;
}

void GoldenImage::write(const std::string& path, const Image8& image) {
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
    ImageWriter::write(path, image.width, image.height, image.channels, image.pixels.data());
}

} // namespace sb
