// core/PngFile against answers it does not compute itself: what it writes is decoded by tests/PngDecoder.h
// (the PNG specification over zlib, no libpng), and what it reads is assembled here byte by byte (chunks,
// CRCs and a zlib stream of filter-0 rows), so every expected sample is written down in the test.
#include <sys/resource.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <zlib.h>

#include "ForgedPng.h"
#include "PngDecoder.h"
#include "core/Error.h"
#include "core/PngFile.h"

using namespace sb;
namespace fs = std::filesystem;

namespace {

class PngFileTest : public ::testing::Test {
protected:
    void SetUp() override {
        mDir = fs::temp_directory_path() / ("sb-png-" + std::to_string(getpid()));
        fs::remove_all(mDir);
        fs::create_directories(mDir);
    }
    void TearDown() override { fs::remove_all(mDir); }
    std::string path(const std::string& name) const { return (mDir / name).string(); }
    fs::path mDir;
};

/// A PNG of `rows` (each already prefixed with its filter byte 0), with `extra` chunks before IDAT.
std::string pngBytes(uint32_t width, uint32_t height, int depth, int colorType, const std::string& rows,
                     const std::vector<std::pair<std::string, std::string>>& extra = {}) {
    std::string out = "\x89PNG\r\n\x1a\n";
    std::string header;
    test::putBigEndian32(header, width);
    test::putBigEndian32(header, height);
    header += {char(depth), char(colorType), 0, 0, 0};
    test::putChunk(out, "IHDR", header);
    for (const auto& [type, body] : extra) test::putChunk(out, type, body);
    uLongf size = compressBound(uLong(rows.size()));
    std::string z(size, '\0');
    compress(reinterpret_cast<Bytef*>(z.data()), &size, reinterpret_cast<const Bytef*>(rows.data()),
             uLong(rows.size()));
    z.resize(size);
    test::putChunk(out, "IDAT", z);
    test::putChunk(out, "IEND", "");
    return out;
}

void writeBytes(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

std::string bytes(std::initializer_list<int> values) {
    std::string s;
    for (int v : values) s += char(v);
    return s;
}

} // namespace

// Every channel count, with a pattern that makes libpng choose filters other than 0 (gradients), decoded
// independently: the samples must come back exactly, top row first.
TEST_F(PngFileTest, WritesEveryChannelCountAsAnIndependentDecoderReadsIt) {
    const int w = 37, h = 11;
    for (int channels = 1; channels <= 4; ++channels) {
        SCOPED_TRACE(channels);
        std::vector<uint8_t> pixels(size_t(w * h * channels));
        for (size_t i = 0; i < pixels.size(); ++i)
            pixels[i] = uint8_t(i * 7 + (i / size_t(w * channels)) * 13);
        const std::string file = path("c" + std::to_string(channels) + ".png");
        PngFile::write(file, w, h, channels, pixels.data());
        const test::DecodedPng decoded = test::decodePng(file);
        ASSERT_TRUE(decoded.ok) << decoded.why;
        EXPECT_EQ(decoded.width, w);
        EXPECT_EQ(decoded.height, h);
        EXPECT_EQ(decoded.channels, channels);
        EXPECT_EQ(decoded.pixels, pixels);
        const PngImage back = PngFile::read(file);
        EXPECT_EQ(back.bitDepth, 8);
        EXPECT_EQ(back.channels, channels);
        EXPECT_EQ(back.pixels, pixels);
    }
}

// A negative stride writes an image stored bottom-up (GL's read-back order) top row first.
TEST_F(PngFileTest, NegativeStrideWritesBottomUpRowsTopFirst) {
    const std::vector<uint8_t> bottomUp = {1, 2, 3,
                                           4, 5, 6}; // 2x3 grey: rows {1,2}, {3,4}, {5,6} from the bottom
    PngFile::write(path("flip.png"), 2, 3, 1, bottomUp.data() + 4, -2);
    const test::DecodedPng decoded = test::decodePng(path("flip.png"));
    ASSERT_TRUE(decoded.ok) << decoded.why;
    EXPECT_EQ(decoded.pixels, (std::vector<uint8_t>{5, 6, 3, 4, 1, 2}));
}

// Files the suite does not write but a user may hand it (occluder textures): palettes, transparency,
// sub-byte grey and 16-bit samples, each expanded to the documented layout with the stored values.
TEST_F(PngFileTest, ReadsPalettesTransparencySubByteGreyAndSixteenBits) {
    // Palette (colour type 3), 3 entries, entry 1 made half transparent by tRNS: 2x1 pixels {1, 2}.
    writeBytes(path("palette.png"), pngBytes(2, 1, 8, 3, bytes({0, 1, 2}),
                                             {{"PLTE", bytes({10, 20, 30, 40, 50, 60, 70, 80, 90})},
                                              {"tRNS", bytes({255, 128})}}));
    const PngImage palette = PngFile::read(path("palette.png"));
    EXPECT_EQ(palette.channels, 4); // tRNS becomes alpha; entry 2 has none listed, so it is opaque
    EXPECT_EQ(palette.pixels, (std::vector<uint8_t>{40, 50, 60, 128, 70, 80, 90, 255}));

    // 2-bit grey, 4 pixels 0..3 in one byte (0b00011011): scaled by 255 / 3 = 85.
    writeBytes(path("grey2.png"), pngBytes(4, 1, 2, 0, bytes({0, 0x1B})));
    const PngImage grey = PngFile::read(path("grey2.png"));
    EXPECT_EQ(grey.channels, 1);
    EXPECT_EQ(grey.pixels, (std::vector<uint8_t>{0, 85, 170, 255}));

    // 16-bit RGB, one pixel (0x1234, 0x8000, 0xFFFF), stored big-endian: kept as stored by read(),
    // rounded to 8 bits by read8(): 0x1234 * 255 / 65535 = 18.0, 0x8000 -> 127.5 -> 128, 0xFFFF -> 255.
    writeBytes(path("rgb16.png"), pngBytes(1, 1, 16, 2, bytes({0, 0x12, 0x34, 0x80, 0x00, 0xFF, 0xFF})));
    const PngImage deep = PngFile::read(path("rgb16.png"));
    EXPECT_EQ(deep.bitDepth, 16);
    EXPECT_EQ(deep.pixels16, (std::vector<uint16_t>{0x1234, 0x8000, 0xFFFF}));
    EXPECT_FLOAT_EQ(deep.normalized(0, 0, 1), 32768.0f / 65535.0f);
    const PngImage reduced = PngFile::read8(path("rgb16.png"));
    EXPECT_EQ(reduced.bitDepth, 8);
    EXPECT_EQ(reduced.pixels, (std::vector<uint8_t>{18, 128, 255}));
}

// Bad files are bad input naming the file and the reason; nothing is allocated for a header's claim.
TEST_F(PngFileTest, BadFilesAreBadInputNamingTheFile) {
    auto expectBadInput = [&](const std::string& file, const std::string& reason) {
        try {
            PngFile::read(file);
            ADD_FAILURE() << file << " was read";
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), ExitCode::BadInput) << e.what();
            EXPECT_NE(std::string(e.what()).find(file), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
        }
    };
    expectBadInput(path("missing.png"), "No such file");
    writeBytes(path("text.png"), "this is not an image");
    expectBadInput(path("text.png"), "not a PNG");
    const std::string good = pngBytes(4, 1, 8, 0, bytes({0, 1, 2, 3, 4}));
    writeBytes(path("cut.png"), good.substr(0, good.size() - 20)); // cut inside IDAT
    expectBadInput(path("cut.png"), "cut.png");
    std::string crc = good;
    crc[29] ^= 1; // the first byte of IHDR's CRC (signature 8, length 4, type 4, body 13)
    writeBytes(path("crc.png"), crc);
    expectBadInput(path("crc.png"), "CRC");
    // A header claiming 100000 x 100000 (10^10 pixels) is refused before any row is read.
    writeBytes(path("huge.png"), pngBytes(100000, 100000, 8, 0, bytes({0, 0})));
    expectBadInput(path("huge.png"), "huge.png");
}

// A write that cannot happen is a failure (exit 1) naming the file, and leaves no partial file.
TEST_F(PngFileTest, AFailedWriteNamesTheFileAndLeavesNothing) {
    const uint8_t pixel = 0;
    const std::string nowhere = path("no/such/folder/x.png");
    try {
        PngFile::write(nowhere, 1, 1, 1, &pixel);
        ADD_FAILURE() << "written";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ExitCode::Failure);
        EXPECT_NE(std::string(e.what()).find(nowhere), std::string::npos) << e.what();
    }
    EXPECT_THROW(PngFile::write(path("zero.png"), 0, 1, 1, &pixel), Error);
    EXPECT_FALSE(fs::exists(path("zero.png")));
    EXPECT_TRUE(PngFile::hasPngExtension("a/b.PNG"));
    EXPECT_FALSE(PngFile::hasPngExtension("a/b.jpg"));
    EXPECT_FALSE(PngFile::hasPngExtension("png"));
}

namespace {

/// The process's peak resident memory so far, in KiB (getrusage's ru_maxrss never goes down).
long peakRssKiB() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss;
}

std::string readFailure(const std::string& file) {
    try {
        PngFile::read(file);
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ExitCode::BadInput) << e.what();
        return e.what();
    }
    return "read";
}

} // namespace

// Forged 74-byte files whose IHDR (correct CRC) claims a large image: refused with a reason before
// anything is allocated for the pixels. The second claim is within every side limit (16384x16384 RGBA
// at 16 bits: 2 GiB of samples), the old reader's worst case: it allocated and zeroed them all before
// finding the data missing.
TEST_F(PngFileTest, AForgedHeaderIsRefusedBeforeItsPixelsAreAllocated) {
    writeBytes(path("wide.png"), test::forgedPng(65535, 65535, 8, 6));
    const std::string wide = readFailure(path("wide.png"));
    EXPECT_NE(wide.find("wide.png"), std::string::npos) << wide;
    EXPECT_NE(wide.find("claims 65535x65535 pixels, over the 16384 a side"), std::string::npos) << wide;

    const long before = peakRssKiB();
    writeBytes(path("deep.png"), test::forgedPng(16384, 16384, 16, 6));
    const std::string deep = readFailure(path("deep.png"));
    EXPECT_NE(deep.find("claims 16384x16384"), std::string::npos) << deep;
    EXPECT_NE(deep.find("74 bytes of file cannot hold"), std::string::npos) << deep;
    // Under 64 MiB more than before: libpng's state and one row are a few hundred KiB; the old reader
    // grew by 2 GiB here.
    EXPECT_LT(peakRssKiB() - before, 64 * 1024);
}

// Writes are atomic: a new image replaces the old one whole and leaves no temporary file; a write that
// fails (here its temporary name is taken by a folder) keeps the old file byte for byte; a symbolic link
// planted at the temporary name is removed, not written through.
TEST_F(PngFileTest, AWriteReplacesWholeOrNotAtAllAndFollowsNoPlantedLink) {
    const uint8_t dark[4] = {0, 0, 0, 0}, light[4] = {255, 255, 255, 255};
    const std::string image = path("image.png");
    PngFile::write(image, 2, 2, 1, dark);
    PngFile::write(image, 2, 2, 1, light);
    EXPECT_EQ(PngFile::read(image).pixels, std::vector<uint8_t>(light, light + 4));
    EXPECT_FALSE(fs::exists(PngFile::tempPathFor(image)));

    const std::string before = [&] {
        std::ifstream in(image, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    }();
    fs::create_directory(PngFile::tempPathFor(image)); // a folder that is not empty: it cannot be removed
    writeBytes(PngFile::tempPathFor(image) + "/keep", "x");
    try {
        PngFile::write(image, 2, 2, 1, dark);
        ADD_FAILURE() << "written through a folder";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ExitCode::Failure);
        EXPECT_EQ(std::string(e.what()).rfind("cannot write image '" + image +
                                                  "': cannot create temporary file '" +
                                                  PngFile::tempPathFor(image) + "'",
                                              0),
                  0u)
            << e.what();
    }
    std::ifstream in(image, std::ios::binary);
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), before);
    fs::remove_all(PngFile::tempPathFor(image));

    writeBytes(path("victim.txt"), "outside");
    fs::create_symlink(path("victim.txt"), PngFile::tempPathFor(image));
    PngFile::write(image, 2, 2, 1, dark); // the link is removed, not written through
    EXPECT_EQ(PngFile::read(image).pixels, std::vector<uint8_t>(dark, dark + 4));
    EXPECT_FALSE(fs::exists(fs::symlink_status(PngFile::tempPathFor(image))));
    std::ifstream victim(path("victim.txt"), std::ios::binary);
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(victim), {}), "outside");
}
