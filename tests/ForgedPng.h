#pragma once
// PNG files assembled byte by byte for the tests of what the suite reads: chunks with correct CRCs, so
// a reader meets exactly the header a test forges (a size no image has, rows the file cannot hold).
#include <cstdint>
#include <string>

#include <zlib.h>

namespace sb::test {

/// `v` big-endian, as PNG stores every number.
inline void putBigEndian32(std::string& out, uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out += char((v >> shift) & 0xFF);
}

/// Appends a chunk of `type` with `body`, its length and CRC.
inline void putChunk(std::string& out, const std::string& type, const std::string& body) {
    putBigEndian32(out, uint32_t(body.size()));
    const std::string typed = type + body;
    out += typed;
    putBigEndian32(out,
                   uint32_t(crc32(0L, reinterpret_cast<const Bytef*>(typed.data()), uInt(typed.size()))));
}

/// A PNG whose IHDR claims `width` x `height` at `depth` bits of `colorType`, followed by one IDAT of
/// 1000 zero bytes (deflated: a few bytes) and IEND: 74 bytes whatever the claim.
inline std::string forgedPng(uint32_t width, uint32_t height, int depth, int colorType) {
    std::string out = "\x89PNG\r\n\x1a\n";
    std::string header;
    putBigEndian32(header, width);
    putBigEndian32(header, height);
    header += {char(depth), char(colorType), 0, 0, 0};
    putChunk(out, "IHDR", header);
    const std::string zeros(1000, '\0');
    uLongf size = compressBound(uLong(zeros.size()));
    std::string z(size, '\0');
    compress(reinterpret_cast<Bytef*>(z.data()), &size, reinterpret_cast<const Bytef*>(zeros.data()),
             uLong(zeros.size()));
    z.resize(size);
    putChunk(out, "IDAT", z);
    putChunk(out, "IEND", "");
    return out;
}

} // namespace sb::test
