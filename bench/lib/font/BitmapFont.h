#pragma once
// The one pixel font of the suite: 5x7 glyphs for printable ASCII (space to tilde), drawn without any
// font library by the accuracy pictures (bench/lib/images: contact-sheet labels, colour-bar scales) and
// by the viewer's overlay (bench/lib/viewer/Overlay.h, from atlas()). It lives in a folder of its own
// below both: the two draw the same text, and neither may include the other.
//
// Each glyph is 7 rows, top row first; in each row bit 4 is the leftmost column and bit 0 the rightmost.
// A character occupies a kCellWidth x kCellHeight cell (one blank column and row after the glyph), every
// font pixel drawn as a scale x scale block. Capitals and ascenders fill all 7 rows; lowercase letters
// stand on rows 2..6, those with a descender (g, p, q, y) included, so a line has one x-height.
// Characters outside ' '..'~' are a hollow box, so a name with an unexpected character still shows that
// something is there (the overlay, whose atlas holds the printable glyphs only, shows '?' instead).
//
// The table is constexpr and needs neither GL nor an image type, so a test computes the pixels a string
// must produce without rendering it (tests/ErrorMapTest.cpp, tests/ViewerCliTest.cpp).
#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace sb {

class BitmapFont {
public:
    static constexpr int kGlyphWidth = 5, kGlyphHeight = 7; ///< ink columns and rows of a glyph
    static constexpr int kCellWidth = 6, kCellHeight = 8;   ///< the pen's advance; a line's rows
    static constexpr char kFirst = ' ', kLast = '~';
    static constexpr int kGlyphCount = kLast - kFirst + 1;
    using Glyph = std::array<uint8_t, kGlyphHeight>;

    /// The glyph of `c` (the hollow box for anything outside ' '..'~').
    static constexpr const Glyph& glyph(char c);
    /// Whether `c` has ink at column `x` (0 = left) and row `y` (0 = top); false outside the 5x7 glyph,
    /// so a caller may walk a whole cell.
    static constexpr bool pixel(char c, int x, int y) {
        if (x < 0 || x >= kGlyphWidth || y < 0 || y >= kGlyphHeight) return false;
        return (glyph(c)[size_t(y)] >> (kGlyphWidth - 1 - x)) & 1u;
    }

    /// Width in pixels of `text` drawn at `scale` (one line; the last cell's blank column left out).
    static int textWidth(std::string_view text, int scale);
    static int textHeight(int scale) { return kGlyphHeight * scale; }
    /// The longest prefix of `text` whose width at `scale` is at most `maxWidth` pixels.
    static std::string fit(const std::string& text, int maxWidth, int scale);
    /// `text` cut into lines of at most `maxWidth` pixels, each as long as fits (at least one character
    /// per line), at most `maxLines` of them (the rest is dropped). Empty text: no line.
    static std::vector<std::string> wrap(const std::string& text, int maxWidth, int scale, int maxLines);
    /// Every printable glyph side by side in one row, kGlyphWidth columns each, for a texture:
    /// kGlyphCount * kGlyphWidth texels wide, kGlyphHeight tall, row 0 = the glyphs' top row, 255 ink
    /// and 0 blank.
    static std::vector<uint8_t> atlas();

    /// Draws `text` with its top-left corner at (x, y): the set font pixels as scale x scale blocks of
    /// `colour`, nothing else (the background shows through); a scale below 1 counts as 1. `image` is any
    /// picture with fillRect(x, y, width, height, colour) that clips to its border (the accuracy
    /// pictures' RgbImage), so the font depends on no image type. Returns the x after the last cell.
    template <class Image, class Colour>
    static int draw(Image& image, int x, int y, std::string_view text, const Colour& colour, int scale = 1) {
        scale = std::max(1, scale);
        for (char c : text) {
            for (int gy = 0; gy < kGlyphHeight; ++gy)
                for (int gx = 0; gx < kGlyphWidth; ++gx)
                    if (pixel(c, gx, gy))
                        image.fillRect(x + gx * scale, y + gy * scale, scale, scale, colour);
            x += kCellWidth * scale;
        }
        return x;
    }

private:
    static constexpr Glyph kBox = {0b11111, 0b10001, 0b10001, 0b10001, 0b10001, 0b10001, 0b11111};
    // ' ' (0x20) to '~' (0x7e), in order.
    static constexpr std::array<Glyph, kGlyphCount> kGlyphs = {{
        {0b00000, 0b00000, 0b00000, 0b00000, 0b00000, 0b00000, 0b00000}, // ' '
        {0b00100, 0b00100, 0b00100, 0b00100, 0b00100, 0b00000, 0b00100}, // !
        {0b01010, 0b01010, 0b01010, 0b00000, 0b00000, 0b00000, 0b00000}, // "
        {0b01010, 0b01010, 0b11111, 0b01010, 0b11111, 0b01010, 0b01010}, // #
        {0b00100, 0b01111, 0b10100, 0b01110, 0b00101, 0b11110, 0b00100}, // $
        {0b11000, 0b11001, 0b00010, 0b00100, 0b01000, 0b10011, 0b00011}, // %
        {0b01100, 0b10010, 0b10100, 0b01000, 0b10101, 0b10010, 0b01101}, // &
        {0b01100, 0b00100, 0b01000, 0b00000, 0b00000, 0b00000, 0b00000}, // '
        {0b00010, 0b00100, 0b01000, 0b01000, 0b01000, 0b00100, 0b00010}, // (
        {0b01000, 0b00100, 0b00010, 0b00010, 0b00010, 0b00100, 0b01000}, // )
        {0b00000, 0b00100, 0b10101, 0b01110, 0b10101, 0b00100, 0b00000}, // *
        {0b00000, 0b00100, 0b00100, 0b11111, 0b00100, 0b00100, 0b00000}, // +
        {0b00000, 0b00000, 0b00000, 0b00000, 0b01100, 0b00100, 0b01000}, // ,
        {0b00000, 0b00000, 0b00000, 0b11111, 0b00000, 0b00000, 0b00000}, // -
        {0b00000, 0b00000, 0b00000, 0b00000, 0b00000, 0b01100, 0b01100}, // .
        {0b00000, 0b00001, 0b00010, 0b00100, 0b01000, 0b10000, 0b00000}, // /
        {0b01110, 0b10001, 0b10011, 0b10101, 0b11001, 0b10001, 0b01110}, // 0
        {0b00100, 0b01100, 0b00100, 0b00100, 0b00100, 0b00100, 0b01110}, // 1
        {0b01110, 0b10001, 0b00001, 0b00010, 0b00100, 0b01000, 0b11111}, // 2
        {0b11111, 0b00010, 0b00100, 0b00010, 0b00001, 0b10001, 0b01110}, // 3
        {0b00010, 0b00110, 0b01010, 0b10010, 0b11111, 0b00010, 0b00010}, // 4
        {0b11111, 0b10000, 0b11110, 0b00001, 0b00001, 0b10001, 0b01110}, // 5
        {0b00110, 0b01000, 0b10000, 0b11110, 0b10001, 0b10001, 0b01110}, // 6
        {0b11111, 0b00001, 0b00010, 0b00100, 0b01000, 0b01000, 0b01000}, // 7
        {0b01110, 0b10001, 0b10001, 0b01110, 0b10001, 0b10001, 0b01110}, // 8
        {0b01110, 0b10001, 0b10001, 0b01111, 0b00001, 0b00010, 0b01100}, // 9
        {0b00000, 0b01100, 0b01100, 0b00000, 0b01100, 0b01100, 0b00000}, // :
        {0b00000, 0b01100, 0b01100, 0b00000, 0b01100, 0b00100, 0b01000}, // ;
        {0b00010, 0b00100, 0b01000, 0b10000, 0b01000, 0b00100, 0b00010}, // <
        {0b00000, 0b00000, 0b11111, 0b00000, 0b11111, 0b00000, 0b00000}, // =
        {0b01000, 0b00100, 0b00010, 0b00001, 0b00010, 0b00100, 0b01000}, // >
        {0b01110, 0b10001, 0b00001, 0b00010, 0b00100, 0b00000, 0b00100}, // ?
        {0b01110, 0b10001, 0b00001, 0b01101, 0b10101, 0b10101, 0b01110}, // @
        {0b01110, 0b10001, 0b10001, 0b11111, 0b10001, 0b10001, 0b10001}, // A
        {0b11110, 0b10001, 0b10001, 0b11110, 0b10001, 0b10001, 0b11110}, // B
        {0b01110, 0b10001, 0b10000, 0b10000, 0b10000, 0b10001, 0b01110}, // C
        {0b11100, 0b10010, 0b10001, 0b10001, 0b10001, 0b10010, 0b11100}, // D
        {0b11111, 0b10000, 0b10000, 0b11110, 0b10000, 0b10000, 0b11111}, // E
        {0b11111, 0b10000, 0b10000, 0b11110, 0b10000, 0b10000, 0b10000}, // F
        {0b01110, 0b10001, 0b10000, 0b10111, 0b10001, 0b10001, 0b01111}, // G
        {0b10001, 0b10001, 0b10001, 0b11111, 0b10001, 0b10001, 0b10001}, // H
        {0b01110, 0b00100, 0b00100, 0b00100, 0b00100, 0b00100, 0b01110}, // I
        {0b00111, 0b00010, 0b00010, 0b00010, 0b00010, 0b10010, 0b01100}, // J
        {0b10001, 0b10010, 0b10100, 0b11000, 0b10100, 0b10010, 0b10001}, // K
        {0b10000, 0b10000, 0b10000, 0b10000, 0b10000, 0b10000, 0b11111}, // L
        {0b10001, 0b11011, 0b10101, 0b10101, 0b10001, 0b10001, 0b10001}, // M
        {0b10001, 0b10001, 0b11001, 0b10101, 0b10011, 0b10001, 0b10001}, // N
        {0b01110, 0b10001, 0b10001, 0b10001, 0b10001, 0b10001, 0b01110}, // O
        {0b11110, 0b10001, 0b10001, 0b11110, 0b10000, 0b10000, 0b10000}, // P
        {0b01110, 0b10001, 0b10001, 0b10001, 0b10101, 0b10010, 0b01101}, // Q
        {0b11110, 0b10001, 0b10001, 0b11110, 0b10100, 0b10010, 0b10001}, // R
        {0b01111, 0b10000, 0b10000, 0b01110, 0b00001, 0b00001, 0b11110}, // S
        {0b11111, 0b00100, 0b00100, 0b00100, 0b00100, 0b00100, 0b00100}, // T
        {0b10001, 0b10001, 0b10001, 0b10001, 0b10001, 0b10001, 0b01110}, // U
        {0b10001, 0b10001, 0b10001, 0b10001, 0b10001, 0b01010, 0b00100}, // V
        {0b10001, 0b10001, 0b10001, 0b10101, 0b10101, 0b10101, 0b01010}, // W
        {0b10001, 0b10001, 0b01010, 0b00100, 0b01010, 0b10001, 0b10001}, // X
        {0b10001, 0b10001, 0b01010, 0b00100, 0b00100, 0b00100, 0b00100}, // Y
        {0b11111, 0b00001, 0b00010, 0b00100, 0b01000, 0b10000, 0b11111}, // Z
        {0b01110, 0b01000, 0b01000, 0b01000, 0b01000, 0b01000, 0b01110}, // [
        {0b00000, 0b10000, 0b01000, 0b00100, 0b00010, 0b00001, 0b00000}, // backslash
        {0b01110, 0b00010, 0b00010, 0b00010, 0b00010, 0b00010, 0b01110}, // ]
        {0b00100, 0b01010, 0b10001, 0b00000, 0b00000, 0b00000, 0b00000}, // ^
        {0b00000, 0b00000, 0b00000, 0b00000, 0b00000, 0b00000, 0b11111}, // _
        {0b01000, 0b00100, 0b00010, 0b00000, 0b00000, 0b00000, 0b00000}, // `
        {0b00000, 0b00000, 0b01110, 0b00001, 0b01111, 0b10001, 0b01111}, // a
        {0b10000, 0b10000, 0b10110, 0b11001, 0b10001, 0b10001, 0b11110}, // b
        {0b00000, 0b00000, 0b01110, 0b10000, 0b10000, 0b10001, 0b01110}, // c
        {0b00001, 0b00001, 0b01101, 0b10011, 0b10001, 0b10001, 0b01111}, // d
        {0b00000, 0b00000, 0b01110, 0b10001, 0b11111, 0b10000, 0b01110}, // e
        {0b00110, 0b01001, 0b01000, 0b11100, 0b01000, 0b01000, 0b01000}, // f
        {0b00000, 0b00000, 0b01111, 0b10001, 0b01111, 0b00001, 0b01110}, // g
        {0b10000, 0b10000, 0b10110, 0b11001, 0b10001, 0b10001, 0b10001}, // h
        {0b00100, 0b00000, 0b01100, 0b00100, 0b00100, 0b00100, 0b01110}, // i
        {0b00010, 0b00000, 0b00110, 0b00010, 0b00010, 0b10010, 0b01100}, // j
        {0b10000, 0b10000, 0b10010, 0b10100, 0b11000, 0b10100, 0b10010}, // k
        {0b01100, 0b00100, 0b00100, 0b00100, 0b00100, 0b00100, 0b01110}, // l
        {0b00000, 0b00000, 0b11010, 0b10101, 0b10101, 0b10001, 0b10001}, // m
        {0b00000, 0b00000, 0b10110, 0b11001, 0b10001, 0b10001, 0b10001}, // n
        {0b00000, 0b00000, 0b01110, 0b10001, 0b10001, 0b10001, 0b01110}, // o
        {0b00000, 0b00000, 0b11110, 0b10001, 0b11110, 0b10000, 0b10000}, // p
        {0b00000, 0b00000, 0b01101, 0b10011, 0b01111, 0b00001, 0b00001}, // q
        {0b00000, 0b00000, 0b10110, 0b11001, 0b10000, 0b10000, 0b10000}, // r
        {0b00000, 0b00000, 0b01110, 0b10000, 0b01110, 0b00001, 0b11110}, // s
        {0b01000, 0b01000, 0b11100, 0b01000, 0b01000, 0b01001, 0b00110}, // t
        {0b00000, 0b00000, 0b10001, 0b10001, 0b10001, 0b10011, 0b01101}, // u
        {0b00000, 0b00000, 0b10001, 0b10001, 0b10001, 0b01010, 0b00100}, // v
        {0b00000, 0b00000, 0b10001, 0b10001, 0b10101, 0b10101, 0b01010}, // w
        {0b00000, 0b00000, 0b10001, 0b01010, 0b00100, 0b01010, 0b10001}, // x
        {0b00000, 0b00000, 0b10001, 0b10001, 0b01111, 0b00001, 0b01110}, // y
        {0b00000, 0b00000, 0b11111, 0b00010, 0b00100, 0b01000, 0b11111}, // z
        {0b00010, 0b00100, 0b00100, 0b01000, 0b00100, 0b00100, 0b00010}, // {
        {0b00100, 0b00100, 0b00100, 0b00100, 0b00100, 0b00100, 0b00100}, // |
        {0b01000, 0b00100, 0b00100, 0b00010, 0b00100, 0b00100, 0b01000}, // }
        {0b00000, 0b00000, 0b01000, 0b10101, 0b00010, 0b00000, 0b00000}, // ~
    }};
    static_assert(kGlyphs.size() == kGlyphCount, "one glyph per printable ASCII character");
};

constexpr const BitmapFont::Glyph& BitmapFont::glyph(char c) {
    return c < kFirst || c > kLast ? kBox : kGlyphs[size_t(c - kFirst)];
}

// The table's order is the character order (spot checks the compiler makes).
static_assert(BitmapFont::pixel('A', 0, 3) && BitmapFont::pixel('A', 4, 3) && !BitmapFont::pixel('A', 0, 0));
static_assert(BitmapFont::pixel('1', 1, 1) && !BitmapFont::pixel('1', 0, 1));
static_assert(BitmapFont::pixel('~', 0, 3) && BitmapFont::pixel('~', 4, 3) && BitmapFont::pixel('_', 0, 6));

} // namespace sb
