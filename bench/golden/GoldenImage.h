#pragma once
// Golden images on disk: 8-bit PNGs (small, diffable by eye, reviewed like code), read and written
// through core/PngFile.
#include <string>

#include "bench/golden/ImageDiff.h"

namespace sb {

class GoldenImage {
public:
    /// Reads `path` (16-bit files reduced to 8 bits); throws sb::Error naming the path and why when it is
    /// missing, not a PNG, truncated or claims a size its bytes cannot hold (core/PngFile.h).
    static Image8 read(const std::string& path);
    /// Writes `image` to `path` as PNG, creating the parent folder: through "<path>.tmp" and a rename
    /// (ImageWriter::writeAtomic), so a killed update leaves the old golden or the new one.
    static void write(const std::string& path, const Image8& image);
};

} // namespace sb
