#pragma once
// PNG files, read and written with libpng: the goldens, screenshots, visibility images, error maps,
// contact sheets and occluder textures. PNG is the one image format the suite reads and writes (every
// committed image is one), and libpng is its whole codec: a general image library would bring dozens of
// codecs into every process, the measured one included (docs/ARCHITECTURE.md, "Decisions": one of them
// executes an instruction valgrind cannot run when it is loaded, on some CPUs).
//
// Values are the stored ones: no gamma or colour-space conversion, no premultiplied alpha. Rows are
// top first, channels interleaved (grey; grey+alpha; RGB; RGBA).
//
//     PngImage image = PngFile::read("results/goldens/city/none.colour.png"); // 8-bit RGB, 128x128
//     PngFile::write("out.png", w, h, 1, grey.data());
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace sb {

/// A decoded PNG: `bitDepth` 8 (samples in `pixels`) or 16 (samples in `pixels16`, host order).
struct PngImage {
    int width = 0, height = 0;
    int channels = 0; ///< 1 grey, 2 grey + alpha, 3 RGB, 4 RGBA (palettes and transparency expanded)
    int bitDepth = 8;
    std::vector<uint8_t> pixels;    ///< width * height * channels samples when bitDepth is 8
    std::vector<uint16_t> pixels16; ///< the same when bitDepth is 16

    /// Sample `c` of pixel (x, y) in [0, 1] (value / 255 or / 65535), whatever the depth.
    float normalized(int x, int y, int c) const;
};

class PngFile {
public:
    /// The largest width or height read (16384): a header may claim up to 2^31 pixels a side, and no
    /// image the suite reads is near this.
    static constexpr uint32_t kMaxSide = 16384;
    /// The most pixels read: the largest image the suite writes (--size 16384x16384). A header is also
    /// held to its file's size (deflate expands at most 1032:1), so a few bytes claiming a large image
    /// are refused before anything is allocated.
    static constexpr uint64_t kMaxPixels = uint64_t(kMaxSide) * kMaxSide;

    /// True when `path` ends in ".png" (any case): the check of an output name before anything runs.
    static bool hasPngExtension(const std::string& path);

    /// Reads `path`. 1, 2 and 4-bit grey is expanded to 8 bits, palettes to RGB, a tRNS chunk to an alpha
    /// channel; 8 and 16-bit samples are kept as stored. Throws sb::Error(BadInput) naming the path and
    /// the reason (missing, not a PNG, corrupt, larger than kMaxSide or kMaxPixels, a header claiming more
    /// rows than the file can hold). libpng's own messages become that one line; it prints nothing.
    static PngImage read(const std::string& path);
    /// The same, with 16-bit samples reduced to 8 (value * 255 / 65535, rounded): for callers that
    /// compare 8-bit images.
    static PngImage read8(const std::string& path);

    /// Writes 8-bit samples: `channels` 1 to 4, rows `rowStride` bytes apart starting at `pixels`
    /// (default width * channels; negative for an image stored bottom-up, `pixels` then pointing at the
    /// top row), whatever `path`'s extension. Every image the suite writes comes here, and it is written
    /// atomically: into tempPathFor(path) (a stale one removed first, then created exclusively, so no
    /// planted link is followed), each write, the flush and the close checked, then renamed over `path`
    /// (a file there keeps its permissions). A kill
    /// leaves the old file or the new one, never a truncated one. Throws sb::Error(Failure) naming the
    /// path, the temporary file and the OS reason when it cannot be written (folder, disk full); the
    /// temporary file is removed and a file already at `path` is untouched.
    static void write(const std::string& path, int width, int height, int channels, const uint8_t* pixels,
                      std::ptrdiff_t rowStride = 0);
    /// "<path>.tmp", the one temporary name of `path` (the convention of every result file,
    /// bench/lib/output/AtomicFile.h).
    static std::string tempPathFor(const std::string& path);
};

} // namespace sb
