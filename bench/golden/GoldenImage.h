#pragma once
// Golden images on disk: 8-bit PNGs (small, diffable by eye, reviewed like code). Read and written
// through OpenImageIO.
#include <string>

#include "bench/golden/ImageDiff.h"

namespace sb {

class GoldenImage {
public:
    /// Reads `path`; throws sb::Error naming the path when it is missing or not an 8-bit image.
    static Image8 read(const std::string& path);
    /// Writes `image` to `path` (format from the extension), creating the parent folder.
    static void write(const std::string& path, const Image8& image);
};

} // namespace sb
