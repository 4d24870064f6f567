#include "core/PngFile.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include <png.h>

#include "core/Error.h"

namespace sb {

namespace {

// libpng reports errors by calling a handler that must not return; the documented way back is longjmp to
// a setjmp in the caller. A longjmp may not skip a C++ destructor, so the functions that call setjmp
// below hold only trivially destructible locals, and every object with a destructor (the pixels, the
// row pointers, the file) lives in their callers.

/// What libpng needs and what it reported, shared with the error handler through png_get_error_ptr.
struct Codec {
    std::FILE* file = nullptr;
    png_structp png = nullptr;
    png_infop info = nullptr;
    char message[256] = "";
};

[[noreturn]] void onError(png_structp png, png_const_charp text) {
    auto* codec = static_cast<Codec*>(png_get_error_ptr(png));
    std::snprintf(codec->message, sizeof codec->message, "%s", text);
    std::longjmp(png_jmpbuf(png), 1);
}

void onWarning(png_structp, png_const_charp) {
} // warnings (an unknown chunk, a bad CRC in an ancillary one) are not errors

/// The file's own opener, closed by its destructor (also when an error unwinds).
class File {
public:
    File(const std::string& path, const char* mode) : mFile(std::fopen(path.c_str(), mode)) {}
    ~File() {
        if (mFile) std::fclose(mFile);
    }
    File(const File&) = delete;
    File& operator=(const File&) = delete;
    std::FILE* get() const { return mFile; }
    /// Closes now, so that a write error (disk full) is seen; false when fclose failed.
    bool close() {
        std::FILE* f = mFile;
        mFile = nullptr;
        return f && std::fclose(f) == 0;
    }

private:
    std::FILE* mFile;
};

/// The decoded layout after the read transforms, read by the header phase.
struct Layout {
    png_uint_32 width = 0, height = 0;
    int channels = 0, bitDepth = 0;
    size_t rowBytes = 0;
};

/// Reads the header and sets the transforms. False with codec.message set on a libpng error.
bool readHeader(Codec& codec, Layout& layout) {
    if (setjmp(png_jmpbuf(codec.png))) return false;
    png_init_io(codec.png, codec.file);
    png_set_user_limits(codec.png, PngFile::kMaxSide, PngFile::kMaxSide);
    png_read_info(codec.png, codec.info);
    const int colorType = png_get_color_type(codec.png, codec.info);
    const int depth = png_get_bit_depth(codec.png, codec.info);
    if (colorType == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(codec.png);
    if (colorType == PNG_COLOR_TYPE_GRAY && depth < 8) png_set_expand_gray_1_2_4_to_8(codec.png);
    if (png_get_valid(codec.png, codec.info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(codec.png);
    if (depth == 16) png_set_swap(codec.png); // PNG stores big-endian; the samples are read as uint16_t
    png_set_interlace_handling(codec.png);
    png_read_update_info(codec.png, codec.info);
    layout.width = png_get_image_width(codec.png, codec.info);
    layout.height = png_get_image_height(codec.png, codec.info);
    layout.channels = png_get_channels(codec.png, codec.info);
    layout.bitDepth = png_get_bit_depth(codec.png, codec.info);
    layout.rowBytes = png_get_rowbytes(codec.png, codec.info);
    return true;
}

/// Reads the rows into the buffers the caller sized. False with codec.message set on a libpng error.
bool readRows(Codec& codec, png_bytepp rows) {
    if (setjmp(png_jmpbuf(codec.png))) return false;
    png_read_image(codec.png, rows);
    png_read_end(codec.png, nullptr);
    return true;
}

/// Writes the header and rows. False with codec.message set on a libpng error.
bool writeImage(Codec& codec, png_uint_32 width, png_uint_32 height, int colorType, png_bytepp rows) {
    if (setjmp(png_jmpbuf(codec.png))) return false;
    png_init_io(codec.png, codec.file);
    png_set_IHDR(codec.png, codec.info, width, height, 8, colorType, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(codec.png, codec.info);
    png_write_image(codec.png, rows);
    png_write_end(codec.png, nullptr);
    return true;
}

std::string readError(const std::string& path, const std::string& why) {
    return "cannot read image '" + path + "': " + why;
}

} // namespace

float PngImage::normalized(int x, int y, int c) const {
    const size_t i = (size_t(y) * size_t(width) + size_t(x)) * size_t(channels) + size_t(c);
    return bitDepth == 16 ? float(pixels16[i]) / 65535.0f : float(pixels[i]) / 255.0f;
}

bool PngFile::hasPngExtension(const std::string& path) {
    if (path.size() < 4) return false;
    std::string ext = path.substr(path.size() - 4);
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".png";
}

PngImage PngFile::read(const std::string& path) {
    File file(path, "rb");
    if (!file.get()) throw Error(readError(path, std::strerror(errno)));
    png_byte signature[8] = {};
    if (std::fread(signature, 1, sizeof signature, file.get()) != sizeof signature ||
        png_sig_cmp(signature, 0, sizeof signature) != 0)
        throw Error(readError(path, "not a PNG file (PNG is the one image format read)"));

    Codec codec;
    codec.file = file.get();
    codec.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &codec, onError, onWarning);
    if (codec.png) codec.info = png_create_info_struct(codec.png);
    struct Release { // frees libpng's state on every way out, the errors thrown below included
        Codec& c;
        ~Release() { png_destroy_read_struct(&c.png, c.info ? &c.info : nullptr, nullptr); }
    } release{codec};
    if (!codec.info) throw Error(readError(path, "out of memory"), ExitCode::Failure);
    png_set_sig_bytes(codec.png, sizeof signature);

    Layout layout;
    if (!readHeader(codec, layout)) throw Error(readError(path, codec.message));
    if (layout.width == 0 || layout.height == 0 || layout.channels < 1 || layout.channels > 4 ||
        (layout.bitDepth != 8 && layout.bitDepth != 16))
        throw Error(readError(path, "unexpected layout after expansion"));
    PngImage image;
    image.width = int(layout.width);
    image.height = int(layout.height);
    image.channels = layout.channels;
    image.bitDepth = layout.bitDepth;
    const size_t samples = size_t(layout.width) * layout.height * size_t(layout.channels);
    png_bytep base = nullptr;
    if (layout.bitDepth == 16) {
        image.pixels16.resize(samples);
        base = reinterpret_cast<png_bytep>(image.pixels16.data());
    } else {
        image.pixels.resize(samples);
        base = image.pixels.data();
    }
    std::vector<png_bytep> rows(layout.height);
    for (png_uint_32 y = 0; y < layout.height; ++y) rows[y] = base + size_t(y) * layout.rowBytes;
    if (!readRows(codec, rows.data())) throw Error(readError(path, codec.message));
    return image;
}

PngImage PngFile::read8(const std::string& path) {
    PngImage image = read(path);
    if (image.bitDepth == 8) return image;
    image.pixels.resize(image.pixels16.size());
    for (size_t i = 0; i < image.pixels16.size(); ++i)
        image.pixels[i] = uint8_t((uint32_t(image.pixels16[i]) * 255u + 32767u) / 65535u);
    image.pixels16.clear();
    image.bitDepth = 8;
    return image;
}

void PngFile::write(const std::string& path, int width, int height, int channels, const uint8_t* pixels,
                    std::ptrdiff_t rowStride) {
    const std::string what = "cannot write image '" + path + "': ";
    static constexpr int kColorTypes[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                                          PNG_COLOR_TYPE_RGB_ALPHA};
    if (width <= 0 || height <= 0 || channels < 1 || channels > 4 || !pixels)
        throw Error(what + std::to_string(width) + "x" + std::to_string(height) + " with " +
                        std::to_string(channels) + " channels is not an image",
                    ExitCode::Failure);
    if (rowStride == 0) rowStride = std::ptrdiff_t(width) * channels;
    std::vector<png_bytep> rows(static_cast<size_t>(height));
    for (int y = 0; y < height; ++y) rows[size_t(y)] = const_cast<png_bytep>(pixels + y * rowStride);

    File file(path, "wb");
    if (!file.get()) throw Error(what + std::strerror(errno), ExitCode::Failure);
    Codec codec;
    codec.file = file.get();
    codec.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &codec, onError, onWarning);
    if (codec.png) codec.info = png_create_info_struct(codec.png);
    struct Release {
        Codec& c;
        ~Release() { png_destroy_write_struct(&c.png, c.info ? &c.info : nullptr); }
    } release{codec};
    if (!codec.info) throw Error(what + "out of memory", ExitCode::Failure);
    // A failed write leaves no partial file behind (ImageWriter::writeAtomic keeps the old one); only a
    // regular file is removed, never a device the path named.
    auto discard = [&] {
        std::error_code ec;
        if (std::filesystem::is_regular_file(path, ec)) std::filesystem::remove(path, ec);
    };
    if (!writeImage(codec, png_uint_32(width), png_uint_32(height), kColorTypes[channels - 1], rows.data())) {
        file.close();
        discard();
        throw Error(what + codec.message, ExitCode::Failure);
    }
    if (std::fflush(file.get()) != 0 || std::ferror(file.get()) || !file.close()) {
        const std::string why = std::strerror(errno);
        discard();
        throw Error(what + why, ExitCode::Failure);
    }
}

} // namespace sb
