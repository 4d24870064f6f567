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
    int osError = 0; ///< errno when libpng gave up (its "Write Error" after a failed fwrite)
};

// Both handlers are installed on every read and write struct, so libpng never prints: its message
// becomes the one line of the sb::Error the caller throws.
[[noreturn]] void onError(png_structp png, png_const_charp text) {
    auto* codec = static_cast<Codec*>(png_get_error_ptr(png));
    codec->osError = errno;
    std::snprintf(codec->message, sizeof codec->message, "%s", text);
    std::longjmp(png_jmpbuf(png), 1);
}

void onWarning(png_structp, png_const_charp) {
} // warnings (an unknown chunk, a bad CRC in an ancillary one) are not errors

/// Ancillary chunks (text, ICC profiles) may inflate to this much at most: none of the suite's images
/// has one, and libpng's default (8 MB) is what a hostile chunk could otherwise claim per chunk.
constexpr png_alloc_size_t kMaxChunkBytes = png_alloc_size_t(1) << 20;
/// Deflate cannot expand data by more than 1032:1 (a 258-byte match costs at least 2 bits), so the
/// rows a file can hold are bounded by its size: a header claiming more is a lie, refused before the
/// pixels are allocated. The slack covers the zlib and chunk framing of a tiny file.
constexpr uint64_t kMaxDeflateRatio = 1032;
constexpr uint64_t kRatioSlack = 4096;

/// The file's own opener, closed by its destructor (also when an error unwinds).
class File {
public:
    File(const std::string& path, const char* mode) : mFile(std::fopen(path.c_str(), mode)) {}
    explicit File(std::FILE* file) : mFile(file) {}
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

/// The header as stored, before any transform: what the file's size is checked against.
struct StoredHeader {
    png_uint_32 width = 0, height = 0;
    size_t rowBytes = 0; ///< one stored row without its filter byte
};

/// Reads the header as stored. False with codec.message set on a libpng error. libpng's own side limit
/// is its largest (2^31 - 1): the suite's limits are checked after, with a message that says why.
bool readInfo(Codec& codec, StoredHeader& stored) {
    if (setjmp(png_jmpbuf(codec.png))) return false;
    png_init_io(codec.png, codec.file);
    png_set_user_limits(codec.png, PNG_UINT_31_MAX, PNG_UINT_31_MAX);
    png_set_chunk_malloc_max(codec.png, kMaxChunkBytes);
    png_read_info(codec.png, codec.info);
    stored.width = png_get_image_width(codec.png, codec.info);
    stored.height = png_get_image_height(codec.png, codec.info);
    stored.rowBytes = png_get_rowbytes(codec.png, codec.info);
    return true;
}

/// Sets the transforms (which allocate libpng's row buffers: only after the header was believed). False
/// with codec.message set on a libpng error.
bool setTransforms(Codec& codec, Layout& layout) {
    if (setjmp(png_jmpbuf(codec.png))) return false;
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

/// Encodes the image into `file`, then flushes and closes it, checking each step: a full disk may show
/// at any of them (stdio buffers the writes; some file systems report a deferred failure at close).
/// Empty on success, else why it failed (the OS's reason where there is one).
std::string encode(File& file, png_uint_32 width, png_uint_32 height, int colorType, png_bytepp rows) {
    Codec codec;
    codec.file = file.get();
    codec.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &codec, onError, onWarning);
    if (codec.png) codec.info = png_create_info_struct(codec.png);
    struct Release {
        Codec& c;
        ~Release() { png_destroy_write_struct(&c.png, c.info ? &c.info : nullptr); }
    } release{codec};
    if (!codec.info) return "out of memory";
    if (!writeImage(codec, width, height, colorType, rows))
        return codec.osError ? std::strerror(codec.osError) : codec.message;
    errno = 0;
    if (std::fflush(file.get()) != 0 || std::ferror(file.get())) {
        const int err = errno ? errno : EIO;
        return std::strerror(err);
    }
    errno = 0;
    if (!file.close()) return std::strerror(errno ? errno : EIO);
    return "";
}

std::string readError(const std::string& path, const std::string& why) {
    return "cannot read image '" + path + "': " + why;
}

/// libpng's reason for giving up, where "Read Error" (its words for a short read) is said plainly.
std::string libpngReason(const Codec& codec, std::FILE* file) {
    if (std::feof(file)) return "truncated: the file ends before its image does";
    return codec.message;
}

/// Why a header libpng accepted is refused before anything is allocated for its pixels: a side or a
/// pixel count no image of the suite has, or more rows than `fileBytes` of deflate can hold. Empty when
/// it is believable.
std::string implausibleSize(const StoredHeader& h, uint64_t fileBytes) {
    const std::string size = std::to_string(h.width) + "x" + std::to_string(h.height);
    if (h.width > PngFile::kMaxSide || h.height > PngFile::kMaxSide)
        return "its header claims " + size + " pixels, over the " + std::to_string(PngFile::kMaxSide) +
               " a side of the largest image the suite writes";
    if (uint64_t(h.width) * h.height > PngFile::kMaxPixels)
        return "its header claims " + size + " pixels, over the " + std::to_string(PngFile::kMaxPixels) +
               " of the largest image the suite writes";
    const uint64_t stored = (uint64_t(h.rowBytes) + 1) * h.height; // filter byte + samples per row
    if (stored > fileBytes * kMaxDeflateRatio + kRatioSlack)
        return "its header claims " + size + " (" + std::to_string(stored) + " bytes of rows), which " +
               std::to_string(fileBytes) + " bytes of file cannot hold (deflate expands at most " +
               std::to_string(kMaxDeflateRatio) + ":1): truncated or forged";
    return "";
}

/// The size of the open file, its position left at the start.
uint64_t fileSize(std::FILE* file) {
    std::fseek(file, 0, SEEK_END);
    const long size = std::ftell(file);
    std::rewind(file);
    return size > 0 ? uint64_t(size) : 0;
}

std::string writeError(const std::string& path, const std::string& what, int err) {
    return "cannot write image '" + path + "': " + what + (err ? std::string(": ") + std::strerror(err) : "");
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
    std::error_code ec;
    if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
        throw Error(readError(path, "not a regular file")); // a FIFO would block, a device never end
    File file(path, "rb");
    if (!file.get()) throw Error(readError(path, std::strerror(errno)));
    const uint64_t fileBytes = fileSize(file.get());
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

    StoredHeader stored;
    Layout layout;
    if (!readInfo(codec, stored)) throw Error(readError(path, libpngReason(codec, file.get())));
    if (const std::string why = implausibleSize(stored, fileBytes); !why.empty())
        throw Error(readError(path, why));
    if (!setTransforms(codec, layout)) throw Error(readError(path, libpngReason(codec, file.get())));
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
    if (!readRows(codec, rows.data())) throw Error(readError(path, libpngReason(codec, file.get())));
    return image;
}

std::string PngFile::tempPathFor(const std::string& path) {
    return path + ".tmp";
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
    static constexpr int kColorTypes[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                                          PNG_COLOR_TYPE_RGB_ALPHA};
    if (width <= 0 || height <= 0 || channels < 1 || channels > 4 || !pixels)
        throw Error(writeError(path,
                               std::to_string(width) + "x" + std::to_string(height) + " with " +
                                   std::to_string(channels) + " channels is not an image",
                               0),
                    ExitCode::Failure);
    if (rowStride == 0) rowStride = std::ptrdiff_t(width) * channels;
    std::vector<png_bytep> rows(static_cast<size_t>(height));
    for (int y = 0; y < height; ++y) rows[size_t(y)] = const_cast<png_bytep>(pixels + y * rowStride);

    // The temporary name is fixed (a killed writer leaves at most one, removed here) and created
    // exclusively ("x": the open fails on anything already there and never follows a link), so a link
    // planted under that name is removed, not written through.
    const std::string temp = tempPathFor(path);
    std::error_code ec;
    std::filesystem::remove(temp, ec);
    File file(temp, "wbx");
    if (!file.get())
        throw Error(writeError(path, "cannot create temporary file '" + temp + "'", errno),
                    ExitCode::Failure);
    if (std::filesystem::is_regular_file(path, ec)) // the replacement keeps who may read the image
        std::filesystem::permissions(temp, std::filesystem::status(path, ec).permissions(), ec);
    const std::string why =
        encode(file, png_uint_32(width), png_uint_32(height), kColorTypes[channels - 1], rows.data());
    if (!why.empty()) {
        std::filesystem::remove(temp, ec);
        throw Error(writeError(path, "cannot write temporary file '" + temp + "': " + why, 0),
                    ExitCode::Failure);
    }
    std::filesystem::rename(temp, path, ec);
    if (ec) {
        std::error_code ignored;
        std::filesystem::remove(temp, ignored);
        throw Error(writeError(path, "cannot rename '" + temp + "' over it: " + ec.message(), 0),
                    ExitCode::Failure);
    }
}

} // namespace sb
