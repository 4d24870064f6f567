#pragma once
// A second PNG reader for the tests, written from the PNG specification (ISO/IEC 15948: chunks, zlib
// stream, per-row filters 0-4) with zlib's inflate and nothing of libpng: the independent answer that
// core/PngFile's output and the images the bench writes are checked against. Reads what the suite
// writes and what apitrace dumps: 8-bit, non-interlaced, grey / grey+alpha / RGB / RGBA. Anything else
// is reported as unreadable (ok = false, why says what), never guessed.
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <zlib.h>

namespace sb::test {

struct DecodedPng {
    bool ok = false;
    std::string why; ///< what was wrong when !ok
    int width = 0, height = 0, channels = 0;
    std::vector<uint8_t> pixels; ///< top row first, channels interleaved
};

namespace png_detail {

inline uint32_t bigEndian32(const uint8_t* p) {
    return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | uint32_t(p[3]);
}

inline int paeth(int a, int b, int c) {
    const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
    return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

} // namespace png_detail

/// Decodes `path`; checks every chunk's CRC.
inline DecodedPng decodePng(const std::string& path) {
    using namespace png_detail;
    DecodedPng out;
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    const std::string file = s.str();
    const auto* data = reinterpret_cast<const uint8_t*>(file.data());
    static const uint8_t kSignature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
    if (file.size() < 8 || !std::equal(kSignature, kSignature + 8, data)) {
        out.why = "no PNG signature";
        return out;
    }
    std::vector<uint8_t> idat;
    int depth = 0, colorType = -1, interlace = 0;
    bool ended = false;
    for (size_t at = 8; at + 12 <= file.size() && !ended;) {
        const uint32_t length = bigEndian32(data + at);
        if (at + 12 + size_t(length) > file.size()) {
            out.why = "a chunk runs past the end of the file";
            return out;
        }
        const std::string type(file, at + 4, 4);
        const uint8_t* body = data + at + 8;
        const uLong crc = crc32(crc32(0L, Z_NULL, 0), data + at + 4, uInt(4 + length));
        if (crc != bigEndian32(body + length)) {
            out.why = "bad CRC in chunk " + type;
            return out;
        }
        if (type == "IHDR") {
            out.width = int(bigEndian32(body));
            out.height = int(bigEndian32(body + 4));
            depth = body[8];
            colorType = body[9];
            interlace = body[12];
        } else if (type == "IDAT") {
            idat.insert(idat.end(), body, body + length);
        } else if (type == "IEND") {
            ended = true;
        }
        at += 12 + size_t(length);
    }
    const int channelsOf[] = {1, 0, 3, 0, 2, 0, 4};
    if (!ended || colorType < 0 || colorType > 6 || channelsOf[colorType] == 0 || depth != 8 || interlace) {
        out.why = "not an 8-bit non-interlaced grey/RGB(A) PNG with IEND (colour type " +
                  std::to_string(colorType) + ", depth " + std::to_string(depth) + ")";
        return out;
    }
    out.channels = channelsOf[colorType];
    const size_t stride = size_t(out.width) * size_t(out.channels);
    std::vector<uint8_t> raw(size_t(out.height) * (stride + 1));
    uLongf rawSize = uLongf(raw.size());
    if (uncompress(raw.data(), &rawSize, idat.data(), uLong(idat.size())) != Z_OK || rawSize != raw.size()) {
        out.why = "the zlib stream does not inflate to height * (1 + row bytes)";
        return out;
    }
    out.pixels.resize(size_t(out.height) * stride);
    const int bpp = out.channels;
    for (int y = 0; y < out.height; ++y) {
        const uint8_t filter = raw[size_t(y) * (stride + 1)];
        const uint8_t* src = &raw[size_t(y) * (stride + 1) + 1];
        uint8_t* row = &out.pixels[size_t(y) * stride];
        const uint8_t* up = y > 0 ? row - stride : nullptr;
        for (size_t i = 0; i < stride; ++i) {
            const int a = i >= size_t(bpp) ? row[i - size_t(bpp)] : 0, b = up ? up[i] : 0,
                      c = up && i >= size_t(bpp) ? up[i - size_t(bpp)] : 0;
            int predictor = 0;
            switch (filter) {
            case 0:
                predictor = 0;
                break;
            case 1:
                predictor = a;
                break;
            case 2:
                predictor = b;
                break;
            case 3:
                predictor = (a + b) / 2;
                break;
            case 4:
                predictor = paeth(a, b, c);
                break;
            default:
                out.why = "row " + std::to_string(y) + " has filter " + std::to_string(filter);
                return out;
            }
            row[i] = uint8_t(src[i] + predictor);
        }
    }
    out.ok = true;
    return out;
}

} // namespace sb::test
